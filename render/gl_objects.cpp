#include "render/gl_objects.hpp"

#include <cstdio>
#include <stdexcept>
#include <vector>

#include "render/shader_sources.hpp"

namespace pl::gl {

void delete_buffer(GLuint id) {
  glDeleteBuffers(1, &id);
}
void delete_vertex_array(GLuint id) {
  glDeleteVertexArrays(1, &id);
}
void delete_texture(GLuint id) {
  glDeleteTextures(1, &id);
}
void delete_framebuffer(GLuint id) {
  glDeleteFramebuffers(1, &id);
}
void delete_renderbuffer(GLuint id) {
  glDeleteRenderbuffers(1, &id);
}
void delete_program(GLuint id) {
  glDeleteProgram(id);
}

namespace {

template <void (*Gen)(GLsizei, GLuint*)>
GLuint generate() {
  GLuint id = 0;
  Gen(1, &id);
  return id;
}

// Compiles one stage; the caller owns the returned shader name.
GLuint compile(GLenum stage, std::string_view file) {
  const std::string_view src = shader_source(file);
  const GLuint s = glCreateShader(stage);
  const GLchar* text = src.data();
  const GLint length = static_cast<GLint>(src.size());
  glShaderSource(s, 1, &text, &length);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    GLint n = 0;
    glGetShaderiv(s, GL_INFO_LOG_LENGTH, &n);
    std::vector<char> log(static_cast<std::size_t>(n) + 1, '\0');
    glGetShaderInfoLog(s, n, nullptr, log.data());
    glDeleteShader(s);
    throw std::runtime_error("shader " + std::string(file) + " does not compile:\n" + log.data());
  }
  return s;
}

}  // namespace

Buffer::Buffer() : Name(generate<glGenBuffers>()) {}
VertexArray::VertexArray() : Name(generate<glGenVertexArrays>()) {}
Texture::Texture() : Name(generate<glGenTextures>()) {}
Renderbuffer::Renderbuffer() : Name(generate<glGenRenderbuffers>()) {}
Framebuffer::Framebuffer() : Name(generate<glGenFramebuffers>()) {}

void Buffer::data(GLenum target, const void* bytes, std::size_t size, GLenum usage) const {
  glBindBuffer(target, id());
  glBufferData(target, static_cast<GLsizeiptr>(size), bytes, usage);
}

void Buffer::sub_data(GLenum target, const void* bytes, std::size_t size,
                      std::size_t offset) const {
  glBindBuffer(target, id());
  glBufferSubData(target, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(size), bytes);
}

Program::Program(std::string_view vertex, std::string_view geometry, std::string_view fragment)
    : Name(glCreateProgram()) {
  std::vector<GLuint> stages;
  try {
    stages.push_back(compile(GL_VERTEX_SHADER, vertex));
    if (!geometry.empty()) stages.push_back(compile(GL_GEOMETRY_SHADER, geometry));
    stages.push_back(compile(GL_FRAGMENT_SHADER, fragment));
  } catch (...) {
    for (GLuint s : stages) glDeleteShader(s);
    throw;
  }
  for (GLuint s : stages) glAttachShader(id(), s);
  glLinkProgram(id());
  for (GLuint s : stages) {
    glDetachShader(id(), s);
    glDeleteShader(s);
  }
  GLint ok = 0;
  glGetProgramiv(id(), GL_LINK_STATUS, &ok);
  if (!ok) {
    GLint n = 0;
    glGetProgramiv(id(), GL_INFO_LOG_LENGTH, &n);
    std::vector<char> log(static_cast<std::size_t>(n) + 1, '\0');
    glGetProgramInfoLog(id(), n, nullptr, log.data());
    throw std::runtime_error("program " + std::string(vertex) + " + " + std::string(fragment) +
                             " does not link:\n" + log.data());
  }
}

void check_error(const char* what) {
  const GLenum e = glGetError();
  if (e != GL_NO_ERROR)
    throw std::runtime_error(std::string("OpenGL error 0x") + [e] {
      char buf[16];
      std::snprintf(buf, sizeof buf, "%04x", e);
      return std::string(buf);
    }() + " in " + what);
}

}  // namespace pl::gl
