#pragma once
// A GLSL program built from files in shaders/ (DESIGN.md "GL"), written in GLSL 330 core and
// compiled as the context's dialect (glsl_dialect.h: GLSL ES 3.00 in the page). GLSL has no
// #include, so shared files (e.g. lighting.glsl, the lecture's formula) are spliced in right
// after each stage's #version line, together with `#define LUZ_VERTEX_SHADER` (GEOMETRY,
// FRAGMENT) so a shared file can hold stage-specific helpers.
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/functions.h"

namespace luz::gl {

class Program {
public:
  // `stages`: file names in luz::shader_dir() (core/resources.h), stage from the extension (.vert, .geom, .frag).
  // `shared`: files prepended to every stage after its #version line.
  // `defines`: lines ("#define NAME VALUE\n") put before the shared files in every stage, to
  // compile variants of one program.
  // Throws luz::Error (kind gl) naming the file and quoting the driver's log.
  Program(const std::vector<std::string>& stages, const std::vector<std::string>& shared = {},
          const std::string& defines = {});
  ~Program();
  Program(Program&& other) noexcept;
  Program& operator=(Program&& other) noexcept;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  void use() const;
  GLuint id() const { return id_; }
  const std::string& name() const { return name_; }

  // Uniform setters; the program must be in use. Names the program does not use (or that the
  // compiler optimised away) are ignored, as GL does for location -1.
  GLint location(const std::string& uniform);
  void set(const std::string& uniform, int value);
  void set(const std::string& uniform, bool value);
  void set(const std::string& uniform, float value);
  void set(const std::string& uniform, const glm::vec2& value);
  void set(const std::string& uniform, const glm::vec3& value);
  void set(const std::string& uniform, const glm::vec4& value);
  void set(const std::string& uniform, const glm::mat4& value);

private:
  GLuint id_ = 0;
  std::string name_;  // "phong.frag + local.vert", for messages
  std::unordered_map<std::string, GLint> locations_;
};

}  // namespace luz::gl
