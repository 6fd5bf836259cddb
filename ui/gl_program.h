#pragma once
// A linked GLSL program built from vertex and fragment source. Needs a current GL context.
#include <string>

namespace weft::ui {

class GlProgram {
 public:
  // Throws std::runtime_error with the compiler's log (and `name`) when a stage fails.
  GlProgram(const std::string& name, const char* vertexSource, const char* fragmentSource);
  ~GlProgram();
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  unsigned id() const { return id_; }
  void use() const;
  int uniform(const char* name) const;  // location, -1 when the uniform is unused

 private:
  unsigned id_ = 0;
};

}  // namespace weft::ui
