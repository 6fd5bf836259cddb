#include "gl_program.h"

#include <GL/glcorearb.h>

#include <stdexcept>
#include <vector>

namespace weft::ui {
namespace {

GLuint compile(const std::string& name, GLenum stage, const char* source) {
  GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok == GL_TRUE) return shader;
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
  glDeleteShader(shader);
  throw std::runtime_error("OpenGL: the " + std::string(stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                           " shader of '" + name + "' does not compile: " + log.data());
}

}  // namespace

GlProgram::GlProgram(const std::string& name, const char* vertexSource, const char* fragmentSource) {
  GLuint vertex = compile(name, GL_VERTEX_SHADER, vertexSource);
  GLuint fragment = 0;
  try {
    fragment = compile(name, GL_FRAGMENT_SHADER, fragmentSource);
  } catch (...) {
    glDeleteShader(vertex);
    throw;
  }
  id_ = glCreateProgram();
  glAttachShader(id_, vertex);
  glAttachShader(id_, fragment);
  glLinkProgram(id_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::vector<char> log(1024, '\0');
    glGetProgramInfoLog(id_, static_cast<GLsizei>(log.size()), nullptr, log.data());
    glDeleteProgram(id_);
    throw std::runtime_error("OpenGL: program '" + name + "' does not link: " + log.data());
  }
}

GlProgram::~GlProgram() { glDeleteProgram(id_); }

void GlProgram::use() const { glUseProgram(id_); }

int GlProgram::uniform(const char* name) const { return glGetUniformLocation(id_, name); }

}  // namespace weft::ui
