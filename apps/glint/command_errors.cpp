// The exceptions the verbs may meet, each reported once for all of them.
#include "command_errors.h"

#include <cstdio>
#include <exception>
#include <new>

#include "glint/image/image_error.h"
#include "glint/render/resume_file.h"
#include "glint/scene/scene_error.h"
#include "glint/scene/setting_overrides.h"
#include "usage_error.h"

namespace glint::cli {

int reporting_errors(const std::function<int()>& run) {
    try {
        return run();
    } catch (const SceneError& e) {
        std::fputs(format_scene_error(e).c_str(), stderr);
        return kExitBadInput;
    } catch (const UsageError& e) {
        std::fprintf(stderr, "glint: error: %s\n", e.message.c_str());
        return kExitBadInput;
    } catch (const SettingsError& e) {
        std::fprintf(stderr, "glint: error: %s", e.what());
        for (const std::string& note : e.notes()) std::fprintf(stderr, " (%s)", note.c_str());
        std::fputs("\n", stderr);
        return kExitBadInput;
    } catch (const ResumeError& e) {
        std::fprintf(stderr, "glint: error: %s\n", e.what());
        return kExitBadInput;
    } catch (const ImageError& e) {
        std::fprintf(stderr, "glint: error: %s\n", e.what());
        return kExitFailure;
    } catch (const std::bad_alloc&) {
        // Its what() is only "std::bad_alloc", which tells a user nothing.
        std::fputs(
            "glint: error: out of memory: the scene or image is too large for this machine\n",
            stderr);
        return kExitFailure;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint: error: %s\n", e.what());
        return kExitFailure;
    }
}

}  // namespace glint::cli
