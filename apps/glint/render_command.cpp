// `glint render` from start to end: check the output paths, load, apply the options, read the
// resume file when continuing, render (writing checkpoints), write the image (or, interrupted, its
// .partial sibling and the resume file) and the stats, and summarise.
#include "render_command.h"

#include <tbb/info.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "command_errors.h"
#include "frame_sequence.h"
#include "glint/image/atomic_file.h"
#include "glint/image/file_io.h"
#include "glint/image/image_io.h"
#include "glint/image/srgb.h"
#include "glint/render/memory_estimate.h"
#include "glint/render/render.h"
#include "glint/render/render_job.h"
#include "glint/render/render_output.h"
#include "glint/render/render_part.h"
#include "glint/render/resume_file.h"
#include "glint/render/world.h"
#include "glint/scene/animation.h"
#include "glint/scene/load_scene.h"
#include "output_path.h"
#include "phase_times.h"
#include "progress.h"
#include "render_setup.h"
#include "render_summary.h"
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

// Between frames, as before a still's render, Ctrl-C and SIGTERM end glint at once: the frames
// written stay, and the next has not started.
void default_stop_signals() {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
}

// The scene's name with .png, in the current directory; an animation's frames numbered in it.
std::string default_output(const std::string& file, const Scene& scene) {
    return std::filesystem::path(file).stem().string() + (scene.animation ? ".####.png" : ".png");
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
                 "--seed %llu%s%s\n",
                 with_thousands(bad.count).c_str(), at.x, at.y, at.sample,
                 static_cast<unsigned long long>(c.seed), shell_quoted(c.scene).c_str(), at.x, at.y,
                 at.sample, static_cast<unsigned long long>(c.seed),
                 c.frames.empty() ? "" : (" --frame " + c.frames).c_str(),
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

// The samples image and the stats a command asks for, of the image `written`.
void write_extras(const RenderCommand& c, const RenderSettings& s, const RenderResult& result,
                  const std::string& written, const PhaseTimes& phases) {
    if (!c.samples_image.empty())
        write_samples_image(c.samples_image, result.samples_taken, s.samples_per_pixel);
    if (!c.stats_file.empty()) {
        const int threads = c.threads > 0 ? c.threads : tbb::info::default_concurrency();
        write_stats(c.stats_file,
                    stats_json({c.scene, written, s.width, s.height, s.samples_per_pixel, threads,
                                &result, phases, process_seconds()}));
    }
}

// The part --part asks for; the whole render without it.
RenderPart requested_part(const RenderCommand& c) {
    const PartSplit split = c.split == "passes" ? PartSplit::passes : PartSplit::tiles;
    if (c.part.empty()) return RenderPart{1, 1, split};
    const auto part = parse_render_part(c.part, split);
    if (!part)
        throw UsageError{
            "--part: expected I/N, part I of N parts with 1 <= I <= N <= 100000, got \"" + c.part +
            "\""};
    if (!c.samples_image.empty())
        throw UsageError{
            "--samples-image cannot be combined with --part: glint merge writes the image"};
    return *part;
}

// The names one image goes by in what glint prints.
struct ImageNames {
    std::string continuing;  // the command that continues it when stopped
    std::string note;        // the summary's note: "frame 7"; empty for a still
};

// A bad output path fails before anything is rendered.
void check_outputs(const RenderCommand& c, const std::string& output) {
    if (const auto reason = unwritable_image_reason(output)) throw UsageError{*reason};
    if (!c.stats_file.empty())
        if (const auto reason = unwritable_reason(c.stats_file)) throw UsageError{*reason};
    if (!c.samples_image.empty())
        if (const auto reason = unwritable_image_reason(c.samples_image)) throw UsageError{*reason};
}

// The output variables' pictures beside the output, when it holds no layers.
void check_aov_outputs(const std::string& output, const AovSet& aovs) {
    if (holds_aov_layers(output)) return;
    for (const Aov a : aovs.list())
        if (const auto reason = unwritable_image_reason(aov_picture_path(output, a).string()))
            throw UsageError{*reason};
}

// The command that continues a stopped render of `output` (frames from `frames` on).
std::string continuing(const RenderCommand& c, const std::string& output,
                       std::optional<FrameRange> frames) {
    std::string command = "glint render " + shell_quoted(c.scene) + " -o " + shell_quoted(output);
    if (frames)
        command +=
            " --frames " + std::to_string(frames->first) + ".." + std::to_string(frames->last);
    return command + " --resume";
}

// One image, a still or a frame: the render of `scene` to command.output, its files written.
int render_image(const RenderCommand& command, const RenderBackend& backend, Scene scene,
                 const ImageNames& names, PhaseTimes phases) {
    const std::string& output = command.output;
    check_outputs(command, output);
    const AovSet aovs = requested_aovs(command);
    const RenderPart part = requested_part(command);
    // A part's state goes to its own file beside the output, which glint merge writes.
    const std::filesystem::path part_file =
        part.whole() ? std::filesystem::path() : part_file_path(output, part.index, part.count);
    if (!part.whole())
        if (const auto reason = unwritable_reason(part_file)) throw UsageError{*reason};
    check_aov_outputs(output, aovs);
    const Stopwatch building;
    RenderSetup setup = set_up_render(command, std::move(scene), aovs, true);
    phases.build = building.seconds();
    const World& world = *setup.world;
    RenderOptions& options = setup.options;
    const std::vector<std::filesystem::path>& files_read = setup.files_read;
    const RenderSettings& s = world.settings();
    const RenderIdentity identity =
        identify_render(command.scene, files_read, s, options, GLINT_VERSION, part);
    // A part leaves no image of its own when stopped: its state alone.
    const std::filesystem::path resume = resume_path(part.whole() ? std::filesystem::path(output)
                                                                  : part_file),
                                partial = part.whole() ? partial_output_path(output)
                                                       : std::filesystem::path();
    const int passes = pass_count(s.samples_per_pixel, pass_size_of(s, options));
    std::optional<RenderState> saved;
    if (command.resume) {
        saved = read_resume_file(resume, identity, s);
    } else {
        saved = initial_state(s, options);
        if (const auto refusal = part_refusal(part, s, *saved))
            throw UsageError{"--part " + command.part + ": " + *refusal};
        start_part(*saved, part, passes);
    }
    const std::vector<WorkPiece> work = part_work(*saved, part, passes);
    if (!part.whole() && work.empty())
        throw UsageError{"--part " + command.part + ": the resume file holds the part done"};
    if (command.checkpoint_minutes)
        options.after_pass = checkpoint_hook(
            {partial, resume, identity,
             std::chrono::duration<double>(*command.checkpoint_minutes * 60), command.ppm_ascii});
    if (backend.check) backend.check(world, options);
    RenderJob job(world, options, std::move(saved));
    if (backend.engine) job.set_engine(backend.engine);
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
        result = part.whole() ? job.run(observer) : job.run(work, observer);
    }
    report_bad_samples(result.bad_samples, command);

    // An interrupted image goes beside the target, never over it, so a good image from an
    // earlier run survives a Ctrl-C; a finished one makes the files of the stopped render
    // stale.
    const std::string written = !result.complete ? partial.string()
                                : part.whole()   ? output
                                                 : part_file.string();
    const Stopwatch writing;
    if (result.complete && !part.whole()) {
        write_resume_file(part_file, identity, job.state());
        std::error_code ignored;
        std::filesystem::remove(resume, ignored);
    } else if (result.complete) {
        write_image_and_aovs(output, result, command.ppm_ascii);
        std::error_code ignored;
        std::filesystem::remove(resume, ignored);
        std::filesystem::remove(partial, ignored);
    } else {
        save_progress(partial, resume, identity, job.state(), result.image, command.ppm_ascii);
    }
    phases.write = writing.seconds();
    write_extras(command, s, result, written, phases);
    if (!result.complete && !part.whole()) {
        std::fprintf(stderr,
                     "glint: interrupted: %s of %s was not finished\n"
                     "glint: to continue, with the same options: glint render %s -o %s "
                     "--part %s%s --resume (the state is in %s)\n",
                     describe(part).c_str(), output.c_str(), shell_quoted(command.scene).c_str(),
                     shell_quoted(output).c_str(), command.part.c_str(),
                     part.split == PartSplit::passes ? " --split passes" : "", resume.c_str());
        return kExitInterrupted;
    }
    if (!result.complete) {
        const int passes_total = progress.passes_total;
        const int next_pass = job.state().passes_done();
        if (next_pass == 0)
            std::fprintf(stderr,
                         "glint: interrupted in the first pass%s: the image so far is in %s "
                         "(the tiles not yet rendered are black)",
                         passes_total > 1 ? (" of " + std::to_string(passes_total)).c_str() : "",
                         written.c_str());
        else
            std::fprintf(stderr,
                         "glint: interrupted after %d of %d passes: the image so far is in %s",
                         next_pass, passes_total, written.c_str());
        std::fprintf(stderr,
                     "; %s was not written\n"
                     "glint: to continue, with the same options: %s (the state is in %s)\n",
                     output.c_str(), names.continuing.c_str(), resume.c_str());
        return kExitInterrupted;
    }
    if (!command.quiet) {
        if (part.whole())
            print_summary(output, s, result, names.note);
        else
            print_summary(part_file.string(), s, result, describe(part) + " of " + output);
    }
    return 0;
}

// Frame f's command: its files named by their frame, and its frames f alone.
RenderCommand frame_command(const RenderCommand& command, int f) {
    RenderCommand frame = command;
    frame.frames = std::to_string(f);
    frame.output = frame_file(command.output, f);
    if (!frame.stats_file.empty()) frame.stats_file = frame_file(frame.stats_file, f);
    if (!frame.samples_image.empty()) frame.samples_image = frame_file(frame.samples_image, f);
    return frame;
}

// Frames rendered whole, each on one rank (backend.share_frames): rank 0 writes each as it comes
// back, as render_image does, and a stop leaves every frame in flight its partial image and
// resume file. `last` is the sequence's last frame, for the command that continues it.
int render_whole_frames(const RenderCommand& command, const RenderBackend& backend,
                        const Scene& scene, const std::map<int, RenderCommand>& frames, int last,
                        double load_seconds) {
    const AovSet aovs = requested_aovs(command);
    for (const auto& [f, c] : frames) {
        check_outputs(c, c.output);
        check_aov_outputs(c.output, aovs);
    }
    // What rank 0 knows of a frame's render without building its world.
    struct Plan {
        RenderSettings settings;
        RenderOptions options;
        RenderIdentity identity;
    };
    std::map<int, Plan> plans;
    bool warned = false;
    const auto plan = [&](int f) -> Plan& {
        if (const auto found = plans.find(f); found != plans.end()) return found->second;
        PreparedRender p = prepare_render(frames.at(f), scene_at_frame(scene, f), aovs, !warned);
        warned = true;
        RenderIdentity identity = identify_render(command.scene, p.scene.sources.files_read,
                                                  p.scene.settings, p.options, GLINT_VERSION);
        return plans.emplace(f, Plan{p.scene.settings, p.options, std::move(identity)})
            .first->second;
    };
    plan(frames.begin()->first);  // the scene's warnings, and its errors, before any render

    FrameRendering rendering = frame_rendering(command, scene, aovs);
    std::set<int> done, stopped;
    FrameBook book;
    book.fresh_state = [&](int f) { return initial_state(plan(f).settings, plan(f).options); };
    book.text = [&](int f) { return settings_text(plan(f).settings, plan(f).options); };
    book.saved = [&](int f) -> std::optional<RenderState> {
        const RenderCommand& c = frames.at(f);
        if (!c.resume) return std::nullopt;
        return read_resume_file(resume_path(c.output), plan(f).identity, plan(f).settings);
    };
    book.checkpoint = [&](int f, const RenderState& state) {
        const RenderCommand& c = frames.at(f);
        save_progress(partial_output_path(c.output), resume_path(c.output), plan(f).identity, state,
                      resolve_image(state), c.ppm_ascii);
    };
    book.finished = [&](int f, int rank, const RenderState& state, bool complete) {
        const RenderCommand& c = frames.at(f);
        const Plan& p = plan(f);
        RenderResult result = render_result(state, p.options);
        result.complete = complete;
        report_bad_samples(result.bad_samples, c);
        const std::filesystem::path partial = partial_output_path(c.output);
        const std::filesystem::path resume = resume_path(c.output);
        const Stopwatch writing;
        if (complete) {
            write_image_and_aovs(c.output, result, c.ppm_ascii);
            std::error_code ignored;
            std::filesystem::remove(resume, ignored);
            std::filesystem::remove(partial, ignored);
            done.insert(f);
        } else {
            save_progress(partial, resume, p.identity, state, result.image, c.ppm_ascii);
            stopped.insert(f);
        }
        // The frame's world was built by the rank that rendered it.
        PhaseTimes phases{load_seconds, std::nullopt, writing.seconds()};
        write_extras(c, p.settings, result, complete ? c.output : partial.string(), phases);
        if (complete && !command.quiet)
            print_summary(c.output, p.settings, result,
                          "frame " + std::to_string(f) + ", rank " + std::to_string(rank));
        plans.erase(f);
    };

    std::vector<int> list;
    for (const auto& [f, c] : frames) list.push_back(f);
    RenderProgress progress;
    bool all_done = false;
    ignore_stop_signals();
    {
        const ProgressWatcher watcher(progress, false);
        all_done = backend.share_frames(list, rendering, book, progress);
    }
    if (all_done) return 0;
    const auto first_left =
        std::find_if(list.begin(), list.end(), [&](int f) { return done.count(f) == 0; });
    const int first = first_left == list.end() ? last : *first_left;
    std::string names;
    for (const int f : stopped) names += (names.empty() ? "" : ", ") + std::to_string(f);
    if (stopped.empty())
        std::fprintf(stderr, "glint: interrupted between frames\n");
    else
        std::fprintf(stderr,
                     "glint: interrupted: %s %s stopped; each has its image so far beside its "
                     "output (.partial) and its state in a resume file\n",
                     stopped.size() == 1 ? "frame" : "frames", names.c_str());
    std::fprintf(stderr, "glint: to continue, with the same options: %s\n",
                 continuing(command, command.output, FrameRange{first, last}).c_str());
    return kExitInterrupted;
}

// The frames of a sequence, each the scene at its moment, to output's frame files. With
// --resume, a frame with a resume file continues from it, and one whose image is written (with
// no resume file beside it) is done: the sequence goes on at the frame in flight. A backend that
// shares frames out whole takes them, but for a last few, fewer than half its ranks, which are
// rendered one after another, each as a still is.
// The scene was loaded once for them all, in load_seconds.
int render_frames(const RenderCommand& command, const RenderBackend& backend, const Scene& scene,
                  FrameRange frames, double load_seconds) {
    if (!command.part.empty())
        throw UsageError{
            "--part renders a part of one image: share a sequence out by --frames "
            "ranges instead (docs/cluster.md)"};
    for (const auto& [option, path] : {std::pair{"--stats", command.stats_file},
                                       std::pair{"--samples-image", command.samples_image}})
        if (!path.empty() && !names_frames(path))
            throw UsageError{std::string(option) +
                             ": a sequence writes one file a frame: name where the frame's "
                             "number goes with '#' (e.g. stats.####.json)"};
    std::map<int, RenderCommand> todo;
    for (int f = frames.first; f <= frames.last; ++f) {
        RenderCommand frame = frame_command(command, f);
        if (command.resume && !std::filesystem::exists(resume_path(frame.output))) {
            if (std::filesystem::exists(frame.output)) {
                if (!command.quiet)
                    std::fprintf(stderr, "glint: frame %d is done (%s)\n", f, frame.output.c_str());
                continue;
            }
            frame.resume = false;
        }
        todo.emplace(f, std::move(frame));
    }
    // The last frames, if fewer than half the ranks, go across the ranks instead: a round of
    // them a frame to a rank would leave most ranks idle, while a frame across many ranks keeps
    // about half of them busy (bench/README.md's model).
    const std::size_t ranks = std::size_t(backend.ranks), rest = todo.size() % ranks;
    const std::size_t whole =
        backend.share_frames ? todo.size() - (2 * rest < ranks ? rest : 0) : 0;
    if (whole > 0) {
        std::map<int, RenderCommand> shared;
        while (shared.size() < whole) shared.insert(todo.extract(todo.begin()));
        if (const int code =
                render_whole_frames(command, backend, scene, shared, frames.last, load_seconds);
            code != 0)
            return code;
    }
    for (const auto& [f, frame] : todo) {
        default_stop_signals();
        if (backend.begin_frame) backend.begin_frame(f);
        const int code =
            render_image(frame, backend, scene_at_frame(scene, f),
                         {continuing(command, command.output, FrameRange{f, frames.last}),
                          "frame " + std::to_string(f)},
                         PhaseTimes{load_seconds, {}, {}});
        if (code != 0) return code;
    }
    return 0;
}

}  // namespace

int run_render(const RenderCommand& command, const RenderBackend& backend) {
    return reporting_errors([&] {
        // Before loading, what can be checked: a bad output path should fail at once, not after
        // the whole render.
        if (!command.output.empty())
            check_outputs(command, names_frames(command.output) ? frame_file(command.output, 0)
                                                                : command.output);
        requested_aovs(command);
        requested_part(command);
        const Stopwatch loading;
        Scene scene = backend.load ? backend.load(command)
                                   : load_scene(command.scene, command.reading.load_options());
        const double load_seconds = loading.seconds();
        RenderCommand image = command;
        if (image.output.empty()) image.output = default_output(command.scene, scene);
        const auto frames = frames_to_render(command.frames, scene, image.output);
        if (!frames) {
            if (scene.animation && !command.quiet)
                std::fprintf(stderr,
                             "glint: note: the scene is an animation of %d frames: this renders "
                             "frame 0 (name the output with #, as out.####.png, for them all)\n",
                             scene.animation->frames);
            if (backend.begin_frame) backend.begin_frame(0);
            return render_image(image, backend, std::move(scene),
                                {continuing(command, image.output, std::nullopt), ""},
                                PhaseTimes{load_seconds, {}, {}});
        }
        return render_frames(image, backend, scene, *frames, load_seconds);
    });
}

}  // namespace glint::cli
