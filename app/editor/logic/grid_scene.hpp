// A rows x cols network of quads over the unit grid with a gentle bump: the editor's drag
// benchmark scene (4 faces for 2 x 2), generated so it needs no file.
#pragma once

#include "core/scene/scene.hpp"

namespace pl {

Scene make_grid_network_scene(int rows, int cols);

}  // namespace pl
