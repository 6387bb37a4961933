// SOFA's shaders are GLSL 1.10/1.20 written for OpenGL's fixed-function state
// (gl_Vertex, gl_ModelViewMatrix, gl_LightSource[0], gl_FrontMaterial, ...);
// Sinew draws with a 3.3 core context, which has none of it. translate_glsl()
// rewrites such a source as GLSL 3.30: a prelude declares the state as
// `sinew_*` uniforms, inputs and outputs (the renderer sets them as the
// fixed-function pipeline would, render/scene_shader.h), and the built-in names,
// `attribute`, `varying`, `texture2D`, `ftransform()` and `gl_FragColor` are
// renamed token by token (comments and strings included: they are dropped by
// the compiler anyway). `#version` lines are replaced; `#define`s given by the
// scene follow it.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace sinew::render {

enum class GlslStage { vertex, fragment };

// Attribute locations of the translated vertex shaders (the renderer's own: render/gl_renderer.cpp).
constexpr int kGlslVertex = 0, kGlslNormal = 1, kGlslColor = 2, kGlslTexCoord = 3;
constexpr int kGlslMaxLights = 8;

std::string translate_glsl(const std::string& source, GlslStage stage,
                           const std::vector<std::pair<std::string, std::string>>& defines);

}  // namespace sinew::render
