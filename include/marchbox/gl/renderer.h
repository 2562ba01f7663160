// marchbox/gl/renderer.h — draws a scene with its raymarching shader into the current context.
#pragma once

#include "marchbox/gl/buffers.h"
#include "marchbox/gl/shader.h"
#include "marchbox/gl/shader_source.h"
#include "marchbox/image.h"
#include "marchbox/scene.h"

#include <memory>
#include <string>
#include <vector>

namespace mb {

struct RenderOptions {
    RenderMode mode = RenderMode::Shaded;
    bool uber = false;  // the general shader with every feature behind uniforms
    RenderQuality quality;
};

class Renderer {
public:
    // Needs a current context with GL loaded. Builds the quad and reads the driver's limits.
    bool init(std::string* error);

    // Picks (compiling on first use) the program for the scene's feature set and uploads the
    // scene. On a compile or link failure the previous program stays in use and *error holds
    // the log.
    bool setScene(const Scene& scene, const RenderOptions& options, std::string* error);

    // Draws the region [x, x+w) × [y, y+h) of a fullW × fullH image into the viewport's origin.
    void draw(int x, int y, int w, int h, int fullW, int fullH);
    void draw(int width, int height) { draw(0, 0, width, height, width, height); }

    const Program* program() const { return current_; }
    int maxUniformBlockBytes() const { return maxUniformBlock_; }

private:
    struct Cached {
        ShaderFeatures features;
        std::unique_ptr<Program> program;
    };
    Program* programFor(const ShaderFeatures& f, std::string* error);
    void upload(const Scene& scene, const ShaderFeatures& f);
    void setUniforms(const Scene& scene, const ShaderFeatures& f);
    void uploadGrid(const Scene& scene);

    std::vector<Cached> cache_;
    Program* current_ = nullptr;
    ShaderFeatures currentFeatures_;
    VertexArray quad_;
    VertexBuffer quadVertices_;
    IndexBuffer quadIndices_;
    UniformBuffer objects_, materials_, lights_;
    StorageBuffer objectStore_;
    TextureBuffer gridCells_, gridItems_;
    int maxUniformBlock_ = 16384;
    float tanHalfFov_ = 0.0f;
};

// Creates an OSMesa context, renders one width × height frame and reads it back (row 0 at top).
bool renderOffscreen(const Scene& scene, const RenderOptions& options, int width, int height,
                     Image* out, std::string* error);

}  // namespace mb
