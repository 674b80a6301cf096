#include "gl/shader.h"

#include <fstream>
#include <sstream>
#include <utility>

#include <fmt/format.h>
#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"
#include "core/i18n.h"
#include "core/resources.h"
#include "gl/glsl_dialect.h"

namespace luz::gl {

using i18n::tr;
using i18n::trf;

namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file)
    throw Error(ErrorKind::gl, trf("{}: cannot read the shader file", path.string()));
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

struct Stage {
  GLenum type;
  const char* define;
};

Stage stage_of(const std::string& file) {
  const std::string ext = std::filesystem::path(file).extension().string();
  if (ext == ".vert") return {GL_VERTEX_SHADER, "LUZ_VERTEX_SHADER"};
  if (ext == ".geom") return {GL_GEOMETRY_SHADER, "LUZ_GEOMETRY_SHADER"};
  if (ext == ".frag") return {GL_FRAGMENT_SHADER, "LUZ_FRAGMENT_SHADER"};
  throw Error(ErrorKind::gl, trf("{}: unknown shader stage (expected .vert, .geom or .frag)", file));
}

// Compiles one stage as several source strings, numbered for the driver's log:
//   0 = the dialect's header (glsl_dialect.h: the file's #version line on the desktop) and the
//   stage define, 1..k = the shared files, k+1 = the file.
// Each string restarts its line count with #line, so "2:14(3): error" reads as line 14 of
// source 2; the message thrown lists which file each number is.
GLuint compile(const std::string& file, const std::vector<std::string>& shared,
               const std::string& defines) {
  const std::filesystem::path dir = shader_dir();
  const Stage stage = stage_of(file);
  const std::string text = read_text(dir / file);

  const size_t version_at = text.find("#version");
  if (version_at == std::string::npos)
    throw Error(ErrorKind::gl, trf("{}: no #version line", (dir / file).string()));
  const size_t body_at = text.find('\n', version_at);
  const std::string version = text.substr(0, body_at == std::string::npos ? text.size() : body_at);
  size_t version_line = 1;
  for (size_t i = 0; i < version_at; ++i) version_line += text[i] == '\n';

  std::vector<std::string> sources;
  std::string legend = trf("source 0 = {} header", file);
  const GlslDialect dialect = current_glsl_dialect();
  sources.push_back(fmt::format("{}\n#define {} 1\n{}", glsl_header(dialect, version), stage.define, defines));
  for (size_t i = 0; i < shared.size(); ++i) {
    const size_t number = i + 1;
    sources.push_back(fmt::format("#line 1 {}\n{}\n", number, read_text(dir / shared[i])));
    legend += fmt::format(", {} = {}", number, shared[i]);
  }
  const size_t own = shared.size() + 1;
  sources.push_back(fmt::format("#line {} {}\n{}", version_line + 1, own,
                                body_at == std::string::npos ? "" : text.substr(body_at + 1)));
  legend += fmt::format(", {} = {}", own, file);

  std::vector<const char*> pointers;
  for (const std::string& s : sources) pointers.push_back(s.c_str());
  const GLuint shader = glCreateShader(stage.type);
  glShaderSource(shader, GLsizei(pointers.size()), pointers.data(), nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
    glDeleteShader(shader);
    // The driver's log as it wrote it; the sentence around it in the user's language.
    throw Error(ErrorKind::gl, trf("{}: does not compile ({}):", (dir / file).string(), legend) + "\n" +
                                   log.c_str());
  }
  return shader;
}

}  // namespace

Program::Program(const std::vector<std::string>& stages, const std::vector<std::string>& shared,
                 const std::string& defines) {
  for (const std::string& file : stages) name_ += (name_.empty() ? "" : " + ") + file;
  std::vector<GLuint> shaders;
  try {
    for (const std::string& file : stages) shaders.push_back(compile(file, shared, defines));
  } catch (...) {
    for (GLuint shader : shaders) glDeleteShader(shader);
    throw;
  }
  id_ = glCreateProgram();
  for (GLuint shader : shaders) glAttachShader(id_, shader);
  glLinkProgram(id_);
  for (GLuint shader : shaders) {
    glDetachShader(id_, shader);
    glDeleteShader(shader);
  }
  GLint ok = GL_FALSE;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint length = 0;
    glGetProgramiv(id_, GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(std::max(length, 1)), '\0');
    glGetProgramInfoLog(id_, GLsizei(log.size()), nullptr, log.data());
    glDeleteProgram(id_);
    id_ = 0;
    throw Error(ErrorKind::gl, trf("{} (in {}): does not link:", name_, shader_dir().string()) + "\n" +
                                   log.c_str());
  }
}

Program::~Program() {
  if (id_) glDeleteProgram(id_);
}

Program::Program(Program&& other) noexcept
    : id_(std::exchange(other.id_, 0)), name_(std::move(other.name_)),
      locations_(std::move(other.locations_)) {}

Program& Program::operator=(Program&& other) noexcept {
  if (this != &other) {
    if (id_) glDeleteProgram(id_);
    id_ = std::exchange(other.id_, 0);
    name_ = std::move(other.name_);
    locations_ = std::move(other.locations_);
  }
  return *this;
}

void Program::use() const { glUseProgram(id_); }

GLint Program::location(const std::string& uniform) {
  auto found = locations_.find(uniform);
  if (found != locations_.end()) return found->second;
  const GLint at = glGetUniformLocation(id_, uniform.c_str());
  locations_.emplace(uniform, at);
  return at;
}

void Program::set(const std::string& uniform, int value) { glUniform1i(location(uniform), value); }
void Program::set(const std::string& uniform, bool value) {
  glUniform1i(location(uniform), value ? 1 : 0);
}
void Program::set(const std::string& uniform, float value) {
  glUniform1f(location(uniform), value);
}
void Program::set(const std::string& uniform, const glm::vec2& value) {
  glUniform2f(location(uniform), value.x, value.y);
}
void Program::set(const std::string& uniform, const glm::vec3& value) {
  glUniform3f(location(uniform), value.x, value.y, value.z);
}
void Program::set(const std::string& uniform, const glm::vec4& value) {
  glUniform4f(location(uniform), value.x, value.y, value.z, value.w);
}
void Program::set(const std::string& uniform, const glm::mat4& value) {
  glUniformMatrix4fv(location(uniform), 1, GL_FALSE, glm::value_ptr(value));
}

}  // namespace luz::gl
