#pragma once
// The four fabrics of the thesis' user study (§3.4, §4.5) and the two elasticity groups it sorted
// them into from the mean elasticity coefficients of Table 4.14 (§4.5.2.1): denim and pants are
// stiff (the thesis' "group one"), t-shirt and swimsuit stretchy ("group two").
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace weft::study {

enum class Fabric { Denim, TShirt, Pants, Swimsuit };
enum class ElasticityGroup { Stiff, Stretchy };

// In the thesis' column order (Tables 4.11 and 4.17), which the analysis keeps.
inline constexpr std::array<Fabric, 4> kFabrics{Fabric::Denim, Fabric::TShirt, Fabric::Pants, Fabric::Swimsuit};
inline constexpr std::array<ElasticityGroup, 2> kElasticityGroups{ElasticityGroup::Stiff, ElasticityGroup::Stretchy};

// The names used in answer files and reports: denim, t-shirt, pants, swimsuit; stiff, stretchy.
std::string_view fabricName(Fabric fabric);
std::string_view groupName(ElasticityGroup group);
std::optional<Fabric> parseFabric(std::string_view name);
std::optional<ElasticityGroup> parseGroup(std::string_view name);

ElasticityGroup groupOf(Fabric fabric);

// The material preset (presets/materials) the study's clips simulate each fabric with: the Wang
// 2011 measurements the thesis names (presets/materials/README.md).
std::string_view materialPresetOf(Fabric fabric);

inline int indexOf(Fabric fabric) { return static_cast<int>(fabric); }
inline int indexOf(ElasticityGroup group) { return static_cast<int>(group); }

}  // namespace weft::study
