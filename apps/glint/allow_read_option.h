// `--allow-read DIR`, shared by the verbs that load a scene: the folders a scene may read besides
// its own (glint's sandbox, docs/reliability.md).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace glint::cli {

// Repeatable; a folder that does not exist is bad usage (exit 2), not a scene error later.
inline void add_allow_read_option(CLI::App& command, std::vector<std::string>& folders) {
    command
        .add_option("--allow-read", folders,
                    "Let the scene read files under DIR too (textures, meshes); it reads only "
                    "under its own folder otherwise. Repeatable")
        ->type_name("DIR")
        // Without a description of its own, the check's would read "DIR:DIR" in the help.
        ->check(CLI::Validator(CLI::ExistingDirectory).description(""))
        // One folder an occurrence, so that the scene after it is not taken for a second.
        ->expected(1)
        ->allow_extra_args(false)
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

}  // namespace glint::cli
