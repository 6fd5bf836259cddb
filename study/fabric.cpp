#include "fabric.h"

namespace weft::study {

std::string_view fabricName(Fabric fabric) {
  switch (fabric) {
    case Fabric::Denim:
      return "denim";
    case Fabric::TShirt:
      return "t-shirt";
    case Fabric::Pants:
      return "pants";
    case Fabric::Swimsuit:
      return "swimsuit";
  }
  return "?";
}

std::string_view groupName(ElasticityGroup group) { return group == ElasticityGroup::Stiff ? "stiff" : "stretchy"; }

std::optional<Fabric> parseFabric(std::string_view name) {
  for (Fabric fabric : kFabrics) {
    if (fabricName(fabric) == name) return fabric;
  }
  return std::nullopt;
}

std::optional<ElasticityGroup> parseGroup(std::string_view name) {
  for (ElasticityGroup group : kElasticityGroups) {
    if (groupName(group) == name) return group;
  }
  return std::nullopt;
}

ElasticityGroup groupOf(Fabric fabric) {
  return fabric == Fabric::Denim || fabric == Fabric::Pants ? ElasticityGroup::Stiff : ElasticityGroup::Stretchy;
}

std::string_view materialPresetOf(Fabric fabric) {
  switch (fabric) {
    case Fabric::Denim:
      return "11oz-black-denim";
    case Fabric::TShirt:
      return "gray-interlock";
    case Fabric::Pants:
      return "royal-target";
    case Fabric::Swimsuit:
      return "white-swim-solid";
  }
  return "?";
}

}  // namespace weft::study
