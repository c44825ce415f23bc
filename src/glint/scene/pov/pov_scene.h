// POV-Ray scene files (.pov) read into glint's Scene: the language core (pov_parser.h) and its
// items (pov_item_reader.h) mapped onto glint's own parts. POV-Ray's left-handed axes are kept
// as they are, with a left-handed camera, so coordinates and transforms mean what they say in
// the file. docs/povray.md lists what is read, what differs and what is not.
#pragma once

#include <filesystem>
#include <string>

#include "glint/scene/read_sandbox.h"
#include "glint/scene/scene.h"

namespace glint {

Scene load_pov_scene(const std::filesystem::path& file, const ReadSandbox& sandbox);

// The same for a text read as if it were the file `as_file` (for tests).
Scene parse_pov_scene(std::string text, const std::filesystem::path& as_file,
                      const ReadSandbox& sandbox);

}  // namespace glint
