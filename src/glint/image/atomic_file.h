// Writing a file so that readers only ever see the old or the complete new contents: an
// interrupted render never leaves a half-written image over a good one (DESIGN principle 5).
#pragma once

#include <filesystem>
#include <functional>

namespace glint {

// Calls `write` with a temporary path in target's directory (".<stem>.tmp-<pid>-<n><ext>", so
// the real extension stays last for libraries that look at it), then renames the temporary
// over `target`. If `write` throws, the temporary is removed and the exception propagates,
// leaving any existing target untouched; an ImageError about the temporary is rethrown naming
// `target` instead (in its message too), since the temporary is a detail the user never asked
// for. A failed rename throws ImageError.
void write_file_atomically(
    const std::filesystem::path& target,
    const std::function<void(const std::filesystem::path& temporary)>& write);

}  // namespace glint
