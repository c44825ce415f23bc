// The image and its output variables, and the state of a stopped render, written to files.
#include "glint/render/render_output.h"

#include <memory>
#include <string>
#include <vector>

#include "glint/image/image_format.h"
#include "glint/image/image_io.h"
#include "glint/render/film/aov_picture.h"

namespace glint {

bool holds_aov_layers(const std::filesystem::path& output) {
    return format_from_extension(output) == ImageFormat::exr;
}

std::filesystem::path aov_picture_path(const std::filesystem::path& output, Aov aov) {
    std::filesystem::path p = output;
    p.replace_filename(output.stem().string() + "." + std::string(aov_info(aov).name) + ".png");
    return p;
}

void write_image_and_aovs(const std::filesystem::path& output, const RenderResult& result,
                          bool ppm_ascii) {
    if (holds_aov_layers(output)) {
        const std::vector<ExrLayer> layers = aov_exr_layers(result.aovs);
        write_image(output, result.image, WriteOptions{.exr_layers = layers});
        return;
    }
    write_image(output, result.image, WriteOptions{ppm_ascii});
    for (const AovImage& layer : result.aovs)
        write_image(aov_picture_path(output, layer.aov), aov_picture(layer), WriteOptions{});
}

void save_progress(const std::filesystem::path& partial, const std::filesystem::path& resume,
                   const RenderIdentity& identity, const RenderState& state, const Image& image,
                   bool ppm_ascii) {
    if (!partial.empty()) write_image(partial, image, WriteOptions{ppm_ascii});
    write_resume_file(resume, identity, state);
}

std::function<void(const RenderState&)> checkpoint_hook(CheckpointPolicy policy) {
    using Clock = std::chrono::steady_clock;
    // Shared by the hook's copies (a job copies its options for each run).
    auto last = std::make_shared<Clock::time_point>(Clock::now());
    return [policy = std::move(policy), last](const RenderState& so_far) {
        if (Clock::now() - *last < policy.interval) return;
        save_progress(policy.partial, policy.resume, policy.identity, so_far,
                      policy.partial.empty() ? Image{} : resolve_image(so_far), policy.ppm_ascii);
        *last = Clock::now();
    };
}

}  // namespace glint
