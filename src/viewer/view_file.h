// `<scene>.view` camera files (spec/user-interfaces.md §3.4), applied when a scene is
// opened and written by "Save camera":
// - SOFA's XML: <Camera> with position, orientation (quaternion x y z w), fieldOfView,
//   distance, zNear, zFar, projectionType children, each with a `value` (lookAt is written
//   but, as in SOFA, the point looked at is position − distance·z on reading);
// - the older two-line text (position, then the quaternion), which runSofa's Qt viewer
//   wrote as `<scene>.view` or `<scene>.qglviewer.view`. SOFA's current viewers ignore it;
//   Sinew reads it too, since ~140 of SOFA's own scenes still ship one.
#pragma once

#include <optional>
#include <string>

#include "render/camera_view.h"

namespace sinew::viewer {

// The camera of `path`; nullopt with *error when the file cannot be read or parsed.
std::optional<render::CameraFrame> read_view_file(const std::string& path, std::string* error);
// The camera file of `scene` (`<scene>.view`, else `<scene>.qglviewer.view`), empty when none.
std::string view_file_for(const std::string& scene);
bool write_view_file(const std::string& path, const render::CameraFrame& f, std::string* error);

}  // namespace sinew::viewer
