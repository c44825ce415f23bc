// A CLI11 check for whole-number options that says what is wrong with a value. CLI11's Range
// reports "--width abc" as "Value abc not in range 1 to 65536", which hides that "abc" is not
// a number at all, and lets "--seed -1" wrap around to 2^64 - 1.
#pragma once

#include <CLI/CLI.hpp>
#include <charconv>
#include <string>
#include <system_error>

namespace glint::cli {

// Accepts decimal whole numbers from min to max inclusive; the message for anything else reads
// `--width: expected a whole number from 1 to 65536, got "abc"`.
template <typename T>
CLI::Validator whole_number(T min, T max) {
    const std::string range = std::to_string(min) + " to " + std::to_string(max);
    return CLI::Validator(
        [min, max, range](std::string& text) -> std::string {
            T value{};
            const char* end = text.data() + text.size();
            const auto [stop, error] = std::from_chars(text.data(), end, value);
            if (error == std::errc() && stop == end && min <= value && value <= max) return {};
            return "expected a whole number from " + range + ", got \"" + text + "\"";
        },
        range);
}

}  // namespace glint::cli
