// Small OpenGL helpers shared by the renderer's files (defined in gl_renderer.cpp). The GL
// context must be current.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace sinew::render {

// One triangle over the viewport, made from gl_VertexID (drawn with an empty vertex array and
// three vertices); v_uv runs over [0, 1]² across the viewport (pixel centres at the texel
// centres of a texture of the viewport's size). Depth 0.5 unless the fragment shader writes one.
extern const char* const kFullViewVertexShader;

// A linked program of the two GLSL sources; 0 with *error (the compiler's or linker's log).
unsigned link_program(const char* vertex, const char* fragment, std::string* error);

// A linked program of the given stages (GL shader type, GLSL source), any number of them; 0
// with *error.
unsigned link_program_stages(const std::vector<std::pair<unsigned, std::string>>& stages, std::string* error);

// Uploads `bytes` into `buffer` bound to `target`, growing its storage only when it is too
// small (`capacity`: the storage's bytes).
void upload_buffer(unsigned target, unsigned buffer, const void* data, std::size_t bytes, std::size_t& capacity);

}  // namespace sinew::render
