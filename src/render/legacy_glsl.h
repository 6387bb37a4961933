// SOFA's shaders are GLSL 1.10/1.20 written for OpenGL's fixed-function state
// (gl_Vertex, gl_ModelViewMatrix, gl_LightSource[0], gl_FrontMaterial, ...);
// Sinew draws with a 3.3 core context, which has none of it. translate_glsl()
// rewrites such a source as GLSL 3.30: a prelude declares the state as
// `sinew_*` uniforms, inputs and outputs (the renderer sets them as the
// fixed-function pipeline would, render/scene_shader.h), and the built-in names,
// `attribute`, `varying`, `texture2D`, `ftransform()` and `gl_FragColor` are
// renamed token by token (comments and strings included: they are dropped by
// the compiler anyway). `#version` lines are replaced; `#define`s given by the
// scene follow it, then the stage's name as SOFA's GLSLShader defines it
// (`VertexShader`, `TessellationControlShader`, `TessellationEvaluationShader`,
// `GeometryShader`, `FragmentShader`: one file can hold every stage). The
// version written is the program's (glsl_program_version): 3.30 for GLSL 1.x,
// the source's own for 4.x (`compatibility` dropped), 4.00 at least with a
// tessellation stage; the tessellation and geometry stages see only the
// uniforms of the prelude, their inputs and outputs being GLSL 1.50's anyway.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace sinew::render {

enum class GlslStage { vertex, tess_control, tess_eval, geometry, fragment };

// Attribute locations of the translated vertex shaders (the renderer's own: render/gl_renderer.cpp).
constexpr int kGlslVertex = 0, kGlslNormal = 1, kGlslColor = 2, kGlslTexCoord = 3;
constexpr int kGlslMaxLights = 8;

// The `#version` number of a source (110, GLSL's default, when it has none).
int glsl_version(const std::string& source);

// The version to write for a program of these sources: at least 330, at least 400 with a
// tessellation stage, else the highest the sources ask for.
int glsl_program_version(const std::vector<std::string>& sources, bool tessellation);

std::string translate_glsl(const std::string& source, GlslStage stage,
                           const std::vector<std::pair<std::string, std::string>>& defines, int version = 330);

}  // namespace sinew::render
