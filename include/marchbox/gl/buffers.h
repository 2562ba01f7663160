// marchbox/gl/buffers.h — RAII, move-only owners of one buffer or vertex array object each.
#pragma once

#include "marchbox/gl/gl.h"

#include <cstddef>
#include <cstdint>
#include <utility>

namespace mb {

// One GL buffer object bound to `Target`. Uploads replace the whole contents.
template <GLenum Target>
class Buffer {
public:
    Buffer() = default;
    ~Buffer() {
        if (id_) glDeleteBuffers(1, &id_);
    }
    Buffer(Buffer&& o) noexcept : id_(std::exchange(o.id_, 0)), size_(o.size_) {}
    Buffer& operator=(Buffer&& o) noexcept {
        std::swap(id_, o.id_);
        std::swap(size_, o.size_);
        return *this;
    }
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;

    void upload(const void* data, size_t bytes, GLenum usage = GL_STATIC_DRAW) {
        if (!id_) glGenBuffers(1, &id_);
        glBindBuffer(Target, id_);
        glBufferData(Target, GLsizeiptr(bytes), data, usage);
        size_ = bytes;
    }
    void bind() const { glBindBuffer(Target, id_); }
    GLuint id() const { return id_; }
    size_t size() const { return size_; }

private:
    GLuint id_ = 0;
    size_t size_ = 0;
};

using VertexBuffer = Buffer<GL_ARRAY_BUFFER>;
using IndexBuffer = Buffer<GL_ELEMENT_ARRAY_BUFFER>;

// A uniform buffer is also bound to an indexed binding point that programs' blocks name.
class UniformBuffer : public Buffer<GL_UNIFORM_BUFFER> {
public:
    void bindBase(GLuint point) const { glBindBufferBase(GL_UNIFORM_BUFFER, point, id()); }
};

class StorageBuffer : public Buffer<GL_SHADER_STORAGE_BUFFER> {
public:
    void bindBase(GLuint point) const { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, point, id()); }
};

// A buffer read by shaders as a usamplerBuffer of 32-bit unsigned integers, or as a
// samplerBuffer of RGBA floats.
class TextureBuffer {
public:
    TextureBuffer() = default;
    ~TextureBuffer() {
        if (texture_) glDeleteTextures(1, &texture_);
    }
    TextureBuffer(TextureBuffer&& o) noexcept
        : buffer_(std::move(o.buffer_)), texture_(std::exchange(o.texture_, 0)) {}
    TextureBuffer& operator=(TextureBuffer&& o) noexcept {
        std::swap(buffer_, o.buffer_);
        std::swap(texture_, o.texture_);
        return *this;
    }
    TextureBuffer(const TextureBuffer&) = delete;
    TextureBuffer& operator=(const TextureBuffer&) = delete;

    void upload(const uint32_t* data, size_t count) {
        uint32_t none = 0;  // a zero-sized buffer texture is not complete
        store(count ? data : &none, (count ? count : 1) * sizeof(uint32_t), GL_R32UI);
    }
    void upload(const float* data, size_t count) {  // count: a multiple of 4
        float none[4] = {};
        store(count ? data : none, (count ? count : 4) * sizeof(float), GL_RGBA32F);
    }
    void bind(GLuint unit) const {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_BUFFER, texture_);
    }

private:
    void store(const void* data, size_t bytes, GLenum format) {
        buffer_.upload(data, bytes, GL_DYNAMIC_DRAW);
        if (!texture_) glGenTextures(1, &texture_);
        glBindTexture(GL_TEXTURE_BUFFER, texture_);
        glTexBuffer(GL_TEXTURE_BUFFER, format, buffer_.id());
    }

    Buffer<GL_TEXTURE_BUFFER> buffer_;
    GLuint texture_ = 0;
};

class VertexArray {
public:
    VertexArray() = default;
    ~VertexArray() {
        if (id_) glDeleteVertexArrays(1, &id_);
    }
    VertexArray(VertexArray&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
    VertexArray& operator=(VertexArray&& o) noexcept {
        std::swap(id_, o.id_);
        return *this;
    }
    VertexArray(const VertexArray&) = delete;
    VertexArray& operator=(const VertexArray&) = delete;

    void bind() {
        if (!id_) glGenVertexArrays(1, &id_);
        glBindVertexArray(id_);
    }

private:
    GLuint id_ = 0;
};

}  // namespace mb
