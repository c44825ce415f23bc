// `glint render` from start to end: check the output paths, load, apply the options, read the
// resume file when continuing, render (writing checkpoints), write the image (or, interrupted, its
// .partial sibling and the resume file) and the stats, and summarise.
#include "render_command.h"

#include <tbb/info.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "command_errors.h"
#include "glint/image/atomic_file.h"
#include "glint/image/file_io.h"
#include "glint/image/image_io.h"
#include "glint/image/srgb.h"
#include "glint/render/memory_estimate.h"
#include "glint/render/render.h"
#include "glint/render/render_job.h"
#include "glint/render/render_output.h"
#include "glint/render/resume_file.h"
#include "glint/render/world.h"
#include "glint/scene/integrator_fit.h"
#include "glint/scene/load_scene.h"
#include "output_path.h"
#include "progress.h"
#include "stats_json.h"
#include "test_hold.h"
#include "usage_error.h"

#ifndef GLINT_VERSION
#define GLINT_VERSION "unknown"
#endif

namespace glint::cli {

namespace {

constexpr int kExitInterrupted = 130;

// From here on SIGINT and SIGTERM are ignored: the render is over and glint only writes its
// files and exits.
void ignore_stop_signals() {
    std::signal(SIGINT, SIG_IGN);
    std::signal(SIGTERM, SIG_IGN);
}

std::string default_output(const std::string& scene) {
    return std::filesystem::path(scene).stem().string() + ".png";
}

// Refuses a render whose structures, film and images would not fit, before building them.
void check_memory(const Scene& scene, AccelKind accel, const RenderCommand& c, AovSet aovs) {
    const MemoryEstimate need = estimate_render_memory(
        scene, accel,
        RenderExtras{
            .samples_image = !c.samples_image.empty(), .resuming = c.resume, .aovs = aovs});
    if (auto refusal = memory_refusal(scene, accel, need, c.max_memory, "--max-memory"))
        throw UsageError{std::move(*refusal)};
}

void print_summary(const std::string& output, const RenderSettings& s, const RenderResult& r) {
    const RayStats& rays = r.rays;
    const double mrays = r.seconds > 0 ? double(rays.total()) / r.seconds / 1e6 : 0;
    if (s.adaptive) {
        // Every pixel's samples are its eye rays.
        const double pixels = double(s.width) * s.height;
        std::printf("glint: wrote %s (%dx%d, adaptive: %.1f of at most %d spp) in %.2f s\n",
                    output.c_str(), s.width, s.height,
                    double(r.rays.traced[std::size_t(RayKind::primary)]) / pixels,
                    s.samples_per_pixel, r.seconds);
    } else {
        std::printf("glint: wrote %s (%dx%d, %d spp) in %.2f s\n", output.c_str(), s.width,
                    s.height, s.samples_per_pixel, r.seconds);
    }
    std::printf("  rays       %15s  %.2f Mrays/s\n", with_thousands(rays.total()).c_str(), mrays);
    for (std::size_t kind = 0; kind < kRayKindCount; ++kind) {
        // The notes' four kinds always; the others when an integrator traced them.
        if (kind > std::size_t(RayKind::refracted) && rays.traced[kind] == 0) continue;
        std::printf("  %-10s %15s", std::string(kRayKindNames[kind]).c_str(),
                    with_thousands(rays.traced[kind]).c_str());
        if (RayKind(kind) == RayKind::primary)
            std::printf("  (%s hit)", with_thousands(rays.primary_hits).c_str());
        std::printf("\n");
    }
    if (rays.shadow_map_lookups > 0)
        std::printf("  shadow-map lookups %7s  (in place of shadow feelers)\n",
                    with_thousands(rays.shadow_map_lookups).c_str());
    if (rays.photons_stored > 0)
        std::printf("  photons    %15s  (%s stored)\n", with_thousands(rays.particles).c_str(),
                    with_thousands(rays.photons_stored).c_str());
    else if (rays.particles > 0)
        std::printf("  particles  %15s  (%s, %.2g%%, reached the eye)\n",
                    with_thousands(rays.particles).c_str(),
                    with_thousands(rays.particles_seen).c_str(),
                    100.0 * double(rays.particles_seen) / double(rays.particles));
}

std::string shell_quoted(const std::string& s) {
    if (s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._-/") ==
        std::string::npos)
        return s;
    std::string quoted = "'";
    for (const char c : s) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

// The count, the first bad sample, and the command that shows its ray tree.
void report_bad_samples(const BadSamples& bad, const RenderCommand& c) {
    if (bad.count == 0) return;
    const SampleLocation& at = *bad.first;
    std::fprintf(stderr,
                 "glint: warning: %s samples were NaN or infinite and were left out; the first "
                 "is pixel (%d, %d), sample %d, seed %llu\n"
                 "glint: to see how it was computed: glint explain %s --pixel %d,%d --sample %d "
                 "--seed %llu%s\n",
                 with_thousands(bad.count).c_str(), at.x, at.y, at.sample,
                 static_cast<unsigned long long>(c.seed), shell_quoted(c.scene).c_str(), at.x, at.y,
                 at.sample, static_cast<unsigned long long>(c.seed),
                 image_options_arguments(c.image).c_str());
}

// Float formats keep the counts; the others show them as a linear ramp of grey, none black and
// the most a pixel may take white: the 8-bit value is 255 count / most, so the value is
// decoded from sRGB first for the encoding to give it back.
void write_samples_image(const std::string& file, Image counts, int most) {
    const std::string ext = std::filesystem::path(file).extension().string();
    const bool keeps_floats = ext == ".exr" || ext == ".EXR" || ext == ".pfm" || ext == ".PFM";
    if (!keeps_floats)
        for (Color& c : counts.pixels) c = Color::gray(srgb_to_linear(c.r / float(most)));
    write_image(file, counts, WriteOptions{});
}

void write_stats(const std::string& file, const std::string& json) {
    write_file_atomically(file, [&](const std::filesystem::path& temporary) {
        UniqueFile out = open_file(temporary, "wb");
        write_bytes(out.get(), json.data(), json.size(), temporary);
        close_written_file(std::move(out), temporary);
    });
}

// The output variables --aov asks for, refused where a render could not write them all.
AovSet requested_aovs(const RenderCommand& c) {
    if (c.aovs.empty()) return {};
    AovSet set;
    try {
        set = parse_aov_list(c.aovs);
    } catch (const std::invalid_argument& e) {
        throw UsageError{std::string("--aov: ") + e.what()};
    }
    if (c.resume || c.checkpoint_minutes)
        throw UsageError{
            "--aov cannot be combined with --resume or --checkpoint: a resume file "
            "does not hold the output variables"};
    return set;
}

}  // namespace

int run_render(const RenderCommand& command) {
    const std::string output =
        command.output.empty() ? default_output(command.scene) : command.output;
    return reporting_errors([&] {
        // Before loading: a bad output path should fail at once, not after the whole render.
        if (const auto reason = unwritable_image_reason(output)) throw UsageError{*reason};
        if (!command.stats_file.empty()) {
            if (const auto reason = unwritable_reason(command.stats_file))
                throw UsageError{*reason};
        }
        if (!command.samples_image.empty()) {
            if (const auto reason = unwritable_image_reason(command.samples_image))
                throw UsageError{*reason};
        }
        const AovSet aovs = requested_aovs(command);
        if (!holds_aov_layers(output))
            for (const Aov a : aovs.list())
                if (const auto reason =
                        unwritable_image_reason(aov_picture_path(output, a).string()))
                    throw UsageError{*reason};
        Scene scene = load_scene(command.scene, command.reading.load_options());
        for (const std::string& warning : scene.warnings)
            std::fprintf(stderr, "glint: warning: %s\n", warning.c_str());
        apply_image_options(command.image, scene.settings);
        check_integrator_fits(scene);
        if (const IntegratorKind k = scene.settings.integrator;
            !aovs.list().empty() && !traces_rays(k)) {
            const std::string name(integrator_name(k));
            throw UsageError{"--aov: the output variables follow rays, and the " + name +
                             " integrator traces " + name + "s"};
        }
        const auto accel = accel_from_name(command.accel);
        if (!accel) throw UsageError{"unknown acceleration structure \"" + command.accel + "\""};
        check_memory(scene, *accel, command, aovs);
        const std::vector<std::filesystem::path> files_read = scene.sources.files_read;
        ShadowAcceleration shadows;
        shadows.light_buffer = command.shadow_accel != "none";
        shadows.occluder_cache = command.shadow_accel == "light-buffer+cache";
        const World world(std::move(scene), *accel, shadows);
        for (const std::string& warning : world.warnings())
            std::fprintf(stderr, "glint: warning: %s\n", warning.c_str());

        RenderOptions options;
        options.threads = command.threads;
        options.seed = command.seed;
        options.record_samples_taken = !command.samples_image.empty();
        options.aovs = aovs;
        const RenderSettings& s = world.settings();
        const RenderIdentity identity =
            identify_render(command.scene, files_read, s, options, GLINT_VERSION);
        const std::filesystem::path resume = resume_path(output),
                                    partial = partial_output_path(output);
        std::optional<RenderState> saved;
        if (command.resume) saved = read_resume_file(resume, identity, s);
        if (command.checkpoint_minutes)
            options.after_pass =
                checkpoint_hook({partial, resume, identity,
                                 std::chrono::duration<double>(*command.checkpoint_minutes * 60),
                                 command.ppm_ascii});
        RenderJob job(world, options, std::move(saved));
        RenderProgress& progress = job.progress();
        // The tests' hold, after each piece of work when they set it.
        const std::function<void(int)> hold = test_hold_from_environment(progress);
        std::atomic<int> pieces_done{0};
        std::function<void(const WorkPiece&)> observer;
        if (hold) observer = [&](const WorkPiece&) { hold(++pieces_done); };
        RenderResult result;
        // Once the samples are in, a Ctrl-C or SIGTERM (a second one sent just as the render
        // ends) would only lose them halfway through writing the files, or turn a written
        // render's exit status into a kill: it is ignored until glint exits. The watcher handles
        // them while it renders, and puts back what it found.
        ignore_stop_signals();
        {
            const ProgressWatcher watcher(progress, !command.quiet);
            result = job.run(observer);
        }
        report_bad_samples(result.bad_samples, command);

        // An interrupted image goes beside the target, never over it, so a good image from an
        // earlier run survives a Ctrl-C; a finished one makes the files of the stopped render
        // stale.
        const std::string written = result.complete ? output : partial.string();
        if (result.complete) {
            write_image_and_aovs(output, result, command.ppm_ascii);
            std::error_code ignored;
            std::filesystem::remove(resume, ignored);
            std::filesystem::remove(partial, ignored);
        } else {
            save_progress(partial, resume, identity, job.state(), result.image, command.ppm_ascii);
        }
        if (!command.samples_image.empty())
            write_samples_image(command.samples_image, result.samples_taken, s.samples_per_pixel);
        if (!command.stats_file.empty()) {
            const int threads =
                command.threads > 0 ? command.threads : tbb::info::default_concurrency();
            write_stats(command.stats_file, stats_json({command.scene, written, s.width, s.height,
                                                        s.samples_per_pixel, threads, &result}));
        }
        if (!result.complete) {
            const int passes = progress.passes_total;
            const int next_pass = job.state().passes_done();
            if (next_pass == 0)
                std::fprintf(stderr,
                             "glint: interrupted in the first pass%s: the image so far is in %s "
                             "(the tiles not yet rendered are black)",
                             passes > 1 ? (" of " + std::to_string(passes)).c_str() : "",
                             written.c_str());
            else
                std::fprintf(stderr,
                             "glint: interrupted after %d of %d passes: the image so far is in %s",
                             next_pass, passes, written.c_str());
            std::fprintf(stderr,
                         "; %s was not written\n"
                         "glint: to continue, with the same options: glint render %s -o %s "
                         "--resume (the state is in %s)\n",
                         output.c_str(), shell_quoted(command.scene).c_str(),
                         shell_quoted(output).c_str(), resume.c_str());
            return kExitInterrupted;
        }
        if (!command.quiet) print_summary(output, s, result);
        return 0;
    });
}

}  // namespace glint::cli
