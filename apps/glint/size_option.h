// A CLI11 option that takes a size as users write it (512M, 16G: glint::parse_bytes), with a
// message that says what a size looks like.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>

#include "glint/render/memory_estimate.h"

namespace glint::cli {

inline void add_size_option(CLI::App& command, const std::string& name,
                            std::optional<std::uint64_t>& target, const std::string& description) {
    command
        .add_option_function<std::string>(
            name, [&target](const std::string& text) { target = parse_bytes(text); }, description)
        ->type_name("SIZE")
        ->check(CLI::Validator(
            [](std::string& text) -> std::string {
                if (parse_bytes(text)) return {};
                return "expected a size such as 512M or 16G, got \"" + text + "\"";
            },
            "SIZE"));
}

}  // namespace glint::cli
