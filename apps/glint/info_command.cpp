// `glint info` from start to end: load, count, lint, build the structure, print.
#include "info_command.h"

#include <cstdio>
#include <utility>

#include "command_errors.h"
#include "glint/accel/make_aggregate.h"
#include "glint/render/world.h"
#include "glint/scene/load_scene.h"
#include "glint/scene/scene_formats.h"
#include "info_report.h"

namespace glint::cli {

namespace {}  // namespace

CLI::App* add_info_command(CLI::App& app, InfoCommand& c) {
    CLI::App* info = app.add_subcommand(
        "info", "Count what a scene holds, describe its acceleration structure, and lint it");
    info->add_option("scene", c.scene, "Scene file: " + scene_formats_text())->required();
    std::vector<std::string> accels;
    for (const std::string_view name : accel_names()) accels.emplace_back(name);
    info->add_option("--accel", c.accel,
                     "Acceleration structure to build and describe (default: bvh, as render)")
        ->check(CLI::IsMember(accels));
    info->add_flag("--json", c.json, "Print one JSON object instead of text");
    add_scene_read_options(*info, c.reading);
    return info;
}

int run_info(const InfoCommand& command) {
    return reporting_errors([&] {
        Scene scene = load_scene(command.scene, command.reading.load_options());
        for (const std::string& warning : scene.warnings)
            std::fprintf(stderr, "glint: warning: %s\n", warning.c_str());
        const AccelKind accel = *accel_from_name(command.accel);  // checked by the parser
        InfoReport report;
        report.scene = command.scene;
        report.settings = scene.settings;
        report.summary = summarize_scene(scene);
        report.warnings = lint_scene(scene);
        report.accel = accel_name(accel);
        const World world(std::move(scene), accel);
        for (const std::string& warning : world.warnings())
            std::fprintf(stderr, "glint: warning: %s\n", warning.c_str());
        report.accel_stats = world.aggregate().statistics();
        const std::string out = command.json ? info_json(report) : info_text(report);
        std::fputs(out.c_str(), stdout);
        return 0;
    });
}

}  // namespace glint::cli
