// `glint bench`: loads a scene, makes its ray sets once, and measures each structure on them.
#include "bench_command.h"

#include <tbb/info.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "command_errors.h"
#include "glint/accel/make_aggregate.h"
#include "glint/render/accel_benchmark.h"
#include "glint/render/json_string.h"
#include "glint/render/memory_estimate.h"
#include "glint/render/ray_sets.h"
#include "glint/render/world.h"
#include "glint/scene/load_scene.h"
#include "glint/scene/scene_formats.h"
#include "scene_read_options.h"
#include "usage_error.h"

namespace glint::cli {

namespace {

constexpr int kRepetitions = 3;  // each figure is the best of these

struct Row {
    std::string_view accel;
    std::string_view rays;
    std::size_t ray_count = 0;
    int threads = 0;
    double build_s = 0;
    double mrays_per_s = 0;
    double bytes_per_prim = 0;
    std::uint64_t hits = 0;
    int packet = 1;  // rays traced together
};

void print_json(const Row& r, const std::string& scene, std::size_t primitives) {
    std::printf(
        "{\"accel\": %s, \"scene\": %s, \"rays\": %s, \"ray_count\": %zu, \"threads\": %d, "
        "\"build_s\": %.6g, \"mrays_per_s\": %.6g, \"bytes_per_prim\": %.6g, \"primitives\": %zu, "
        "\"hits\": %llu, \"repetitions\": %d, \"packet\": %d}\n",
        json_string(r.accel).c_str(), json_string(scene).c_str(), json_string(r.rays).c_str(),
        r.ray_count, r.threads, r.build_s, r.mrays_per_s, r.bytes_per_prim, primitives,
        static_cast<unsigned long long>(r.hits), kRepetitions, r.packet);
}

void print_row(const Row& r) {
    const std::string rays =
        std::string(r.rays) + (r.packet > 1 ? " x" + std::to_string(r.packet) : "");
    std::printf("%-8s %-13s %7d %9.4f %9.2f %11.1f %13s\n", std::string(r.accel).c_str(),
                rays.c_str(), r.threads, r.build_s, r.mrays_per_s, r.bytes_per_prim,
                with_thousands(r.hits).c_str());
}

std::vector<AccelKind> chosen_structures(const BenchCommand& c) {
    std::vector<AccelKind> kinds;
    if (c.accels.empty()) {
        for (const std::string_view name : accel_names())
            if (name != "list") kinds.push_back(*accel_from_name(name));
        return kinds;
    }
    for (const std::string& name : c.accels) {
        const auto kind = accel_from_name(name);
        if (!kind) throw UsageError{"unknown acceleration structure \"" + name + "\""};
        if (std::find(kinds.begin(), kinds.end(), *kind) == kinds.end()) kinds.push_back(*kind);
    }
    return kinds;
}

// Whether the set is to be traced: all are when none is named.
bool chosen(const std::vector<std::string>& names, std::string_view set) {
    return names.empty() || std::find(names.begin(), names.end(), set) != names.end();
}

}  // namespace

CLI::App* add_bench_command(CLI::App& app, BenchCommand& c) {
    CLI::App* bench = app.add_subcommand(
        "bench", "Measure every acceleration structure on the same rays of a scene");
    bench->add_option("scene", c.scene, "Scene file: " + scene_formats_text())->required();
    bench->add_flag("--json", c.json, "One JSON object a line (keys in docs/cli.md)");
    std::vector<std::string> names;
    for (const std::string_view name : accel_names()) names.emplace_back(name);
    bench
        ->add_option("--accel", c.accels,
                     "Structures to measure (repeat the option, or separate names with commas); "
                     "default: all but list")
        ->delimiter(',')
        ->allow_extra_args(false)  // `--accel bvh SCENE`: SCENE is not a structure
        ->check(CLI::IsMember(names));
    bench
        ->add_option("--ray-set", c.ray_sets,
                     "Ray sets to trace (repeat the option, or separate names with commas); "
                     "default: all three")
        ->delimiter(',')
        ->allow_extra_args(false)
        ->check(CLI::IsMember({"primary", "incoherent", "shadow"}));
    bench->add_flag("--packets", c.packets,
                    "Also trace each set in packets of eight rays (primary rays in tiles of 4x2 "
                    "pixels), as rows of their own");
    bench->add_option("--threads", c.threads, "The 'all threads' count; 0 uses every core")
        ->check(CLI::Range(0, 4096));
    bench->add_option("--rays", c.rays, "Rays in each set (primary, incoherent, shadow)")
        ->check(CLI::Range(std::size_t(1), kMaxRaysPerSet));
    add_scene_read_options(*bench, c.reading);
    return bench;
}

int run_bench(const BenchCommand& command) {
    return reporting_errors([&] {
        const std::vector<AccelKind> kinds = chosen_structures(command);
        Scene scene = load_scene(command.scene, command.reading.load_options());
        for (const std::string& warning : scene.warnings)
            std::fprintf(stderr, "glint: warning: %s\n", warning.c_str());

        // The BVH finds the surface points the secondary sets start from; every structure then
        // traces the very same rays. No light buffers: they are not measured here, and would
        // build the own BVH of meshes that the structures trace triangle by triangle.
        const World world(std::move(scene), AccelKind::bvh, ShadowAcceleration{false, false});
        const RaySets sets = make_ray_sets(world, command.rays);
        const std::span<const Primitive> primitives = world.primitives();
        const std::size_t counted = triangle_counted_primitives(primitives);
        const std::size_t mesh_bytes = mesh_bvh_bytes(primitives);

        std::vector<int> thread_counts{1};
        const int all = command.threads > 0 ? command.threads : tbb::info::default_concurrency();
        if (all > 1) thread_counts.push_back(all);

        if (!command.json) {
            std::printf("glint bench: %s\n", command.scene.c_str());
            std::printf("  %s primitives (%s counting the triangles of meshes)\n",
                        with_thousands(primitives.size()).c_str(), with_thousands(counted).c_str());
            std::printf(
                "  %s rays a set: primary through a %dx%d image, incoherent and shadow from "
                "%s surface points\n",
                with_thousands(sets.sets[0].rays.size()).c_str(), sets.width, sets.height,
                with_thousands(sets.surface_points).c_str());
            std::printf("  throughput: best of %d runs; build: one run\n\n", kRepetitions);
            std::printf("%-8s %-13s %7s %9s %9s %11s %13s\n", "accel", "rays", "threads", "build s",
                        "Mrays/s", "bytes/prim", "hits");
        }
        std::fflush(stdout);

        // hits[set] -> structure -> count, to show that they agree.
        std::map<std::string_view, std::map<std::string_view, std::uint64_t>> hits;
        bool disagree = false;
        for (const AccelKind kind : kinds) {
            const std::string_view name = accel_name(kind);
            for (const int threads : thread_counts) {
                const BuildMeasure build = measure_build(kind, primitives, threads);
                // glint's structures trace instanced and transformed meshes through the meshes'
                // own BVHs; Embree does not.
                const std::size_t bytes =
                    build.aggregate->memory_bytes() + (name == "embree" ? 0 : mesh_bytes);
                for (const RaySet& set : sets.sets) {
                    if (!chosen(command.ray_sets, set.name)) continue;
                    for (const bool packets : {false, true}) {
                        if (packets && !command.packets) continue;
                        std::optional<RaySet> tiled;
                        if (packets) tiled = in_packet_order(set, sets.width, sets.height);
                        const RaySet& traced = tiled ? *tiled : set;
                        const TraceMeasure trace =
                            measure_trace(*build.aggregate, traced, threads, kRepetitions, packets);
                        const Row row{name,
                                      set.name,
                                      set.rays.size(),
                                      threads,
                                      build.seconds,
                                      trace.mrays_per_second(set.rays.size()),
                                      counted > 0 ? double(bytes) / double(counted) : 0,
                                      trace.hits,
                                      packets ? kRayPacketSize : 1};
                        // Against every structure so far, this one at the other thread count
                        // and in packets too.
                        auto& by_structure = hits[set.name];
                        by_structure.try_emplace(name, trace.hits);
                        for (const auto& [other, count] : by_structure)
                            if (count != trace.hits) disagree = true;
                        if (command.json) {
                            print_json(row, command.scene, counted);
                        } else {
                            print_row(row);
                        }
                        std::fflush(stdout);
                    }
                }
            }
        }
        if (disagree) {
            std::fprintf(stderr, "glint: note: the structures' hit counts differ:");
            for (const auto& [set, by_structure] : hits) {
                std::fprintf(stderr, "\n  %s:", std::string(set).c_str());
                for (const auto& [structure, count] : by_structure)
                    std::fprintf(stderr, " %s %s", std::string(structure).c_str(),
                                 with_thousands(count).c_str());
            }
            std::fputc('\n', stderr);
            if (hits.begin()->second.contains("embree"))
                std::fprintf(stderr,
                             "  (Embree's own triangle test may decide a ray that grazes a "
                             "triangle's edge otherwise)\n");
        } else if (!command.json) {
            std::printf("\nhit counts agree across structures\n");
        }
        return 0;
    });
}

}  // namespace glint::cli
