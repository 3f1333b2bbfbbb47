// Thin RAII owners of OpenGL names. Each needs a current context when created and destroyed;
// they are move-only so a name is deleted exactly once.
#pragma once

#include <string>
#include <string_view>
#include <utility>

#include "render/gl.hpp"

namespace pl::gl {

// Owns one GL name; Deleter(GLuint) frees it.
template <void (*Deleter)(GLuint)>
class Name {
 public:
  Name() = default;
  explicit Name(GLuint id) : id_(id) {}
  ~Name() {
    if (id_) Deleter(id_);
  }
  Name(Name&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Name& operator=(Name&& o) noexcept {
    if (this != &o) {
      if (id_) Deleter(id_);
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  Name(const Name&) = delete;
  Name& operator=(const Name&) = delete;
  GLuint id() const { return id_; }

 private:
  GLuint id_ = 0;
};

void delete_buffer(GLuint id);
void delete_vertex_array(GLuint id);
void delete_texture(GLuint id);
void delete_framebuffer(GLuint id);
void delete_renderbuffer(GLuint id);
void delete_program(GLuint id);

class Buffer : public Name<delete_buffer> {
 public:
  Buffer();
  // (Re)allocates and fills the buffer bound to `target`.
  void data(GLenum target, const void* bytes, std::size_t size, GLenum usage) const;
  // Replaces `size` bytes from byte `offset` of the buffer bound to `target`.
  void sub_data(GLenum target, const void* bytes, std::size_t size, std::size_t offset = 0) const;
};

class VertexArray : public Name<delete_vertex_array> {
 public:
  VertexArray();
  void bind() const { glBindVertexArray(id()); }
};

class Texture : public Name<delete_texture> {
 public:
  Texture();
};

class Renderbuffer : public Name<delete_renderbuffer> {
 public:
  Renderbuffer();
};

class Framebuffer : public Name<delete_framebuffer> {
 public:
  Framebuffer();
};

// A linked program. Compile and link errors throw std::runtime_error with the shader file name
// and the driver's log.
class Program : public Name<delete_program> {
 public:
  // Sources are looked up among the embedded shaders by file name; geometry may be empty.
  Program(std::string_view vertex, std::string_view geometry, std::string_view fragment);
  void use() const { glUseProgram(id()); }
  GLint uniform(const char* name) const { return glGetUniformLocation(id(), name); }
};

// Throws std::runtime_error naming `what` if the GL error flag is set.
void check_error(const char* what);

}  // namespace pl::gl
