// OglFluidModel's screen-space fluid surface (SofaSphFluid), drawn as SOFA draws it.
//
// SOFA renders the particles in eight off-screen passes, each into a target of its own
// (an RGBA8 colour texture and a 24-bit depth texture, as sofa::gl::FrameBufferObject's
// defaults; linear filtering, clamped to the edges), at the size of the picture:
//   0 thickness  every particle a disc of spriteThickness, added up (saturates at 1)
//   1 depth      every particle a sphere of spriteRadius: the nearest surface's depth
//   2, 3         the depth blurred across, then along (a bilateral filter over
//                ±spriteBlurRadius pixels; spatial weight exp(−(x·spriteBlurScale)²) with x
//                in texture units, range weight exp(−(Δdepth·spriteBlurDepthFalloff)²))
//   4 normals    from the blurred depth's differences to the neighbouring pixels (the
//                smaller of the two one-sided differences in z), through the inverse projection
//   5, 6         the thickness blurred likewise
//   7 shade      a headlight along +z: (½ + ½·max(n_z, 0))·spriteDiffuseColor weighted by
//                the thickness, white by (1 − thickness), plus a Blinn highlight of exponent
//                1280; alpha the thickness; depth the blurred depth
// and SOFA's transparent pass lays target 7 over the picture (blended "over", depth-tested
// against the scene). With debugFBO 0 to 6 the opaque pass shows that target's picture
// instead, over the whole view (depth textures as grey); 7 and 8 show nothing of it here
// (SOFA draws an untextured quad in whatever colour is current) and 8 and above also lay the
// surface over the picture.
//
// SOFA's quirks are kept, as they shape the picture: a sprite's size in pixels is
// spriteRadius · width / tan(32.5°) / distance, whatever the camera's field of view; the
// normal pass takes the depth texture's [0, 1] value as the NDC z; its normals are stored in
// an 8-bit target, so negative components read back as 0; the shading pass is given the
// inverse projection transposed. The GL context must be current.
//
// Every pass is scissored to the pixels it can change: the particles' sprites (found on the CPU
// from the same sizes the vertex shader gives them), grown by the blur's reach for the thickness
// blurs, which spread beyond them (for debugFBO 5 and 6). Outside, a target holds its clear value,
// as SOFA's passes over the whole view leave it: the depth passes discard there, and the thickness
// blurs of nothing are 0. Each target clears only what it was last written over, and the
// composition only covers the sprites. On a software renderer this is the difference between
// tens of milliseconds and a few per frame for a fluid filling part of the view.
#pragma once

#include <Eigen/Core>

#include "render/camera_view.h"
#include "render/draw_list.h"

namespace sinew::render {

class FluidSurface {
 public:
  FluidSurface() = default;
  FluidSurface(const FluidSurface&) = delete;
  FluidSurface& operator=(const FluidSurface&) = delete;
  ~FluidSurface();

  // Passes 0 to 7 for the `count` points of `vao` (positions as attribute 0, the same as
  // `positions`, x y z each), seen through `view` in a picture of width × height pixels. Leaves
  // the targets bound and the scissor test on: the caller binds its framebuffer, viewport,
  // scissor, program and state again. False when the programs or targets cannot be made (said
  // once on stderr).
  bool render(unsigned vao, const float* positions, int count, const FluidLook& look, const View& view, int width,
              int height);
  // Over the bound framebuffer's viewport: target `debug` (0 to 6) of the last render, without
  // depth test; nothing for other values.
  void draw_debug(unsigned debug);
  // Over the bound framebuffer's viewport, whose lower-left corner is (x, y): the shaded surface
  // of the last render, blended "over" and depth-tested (writing its depth). Leaves the scissor
  // test off.
  void composite(int x, int y);

  // Pixels [x0, x1) × [y0, y1) of a target.
  struct Rect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool empty() const { return x1 <= x0 || y1 <= y0; }
  };
  // The pixels the sprites of the last render cover (tests).
  Rect sprites() const { return sprites_; }

 private:
  struct Target {
    unsigned fbo = 0, color = 0, depth = 0;
  };
  static constexpr int kTargets = 8;
  bool make(int width, int height);
  void release();
  void full_screen(unsigned program);
  // Binds target `target`, clears what it last held and what `r` covers to (red, 1, 1, 1) or
  // (red, red, red, 1), and scissors to `r`.
  void start(int target, float red, bool grey, Rect r);
  Target targets_[kTargets];
  Rect written_[kTargets];  // where each target may hold other than its clear value
  Rect sprites_;
  int width_ = 0, height_ = 0;
  unsigned sprite_ = 0, blur_depth_ = 0, normals_ = 0, blur_thickness_ = 0, shade_ = 0, over_ = 0, show_ = 0;
  unsigned quad_vao_ = 0;
  bool failed_ = false;
};

}  // namespace sinew::render
