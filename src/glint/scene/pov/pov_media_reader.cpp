// POV-Ray's media { absorption emission scattering { type, colour eccentricity extinction }
// density { } method intervals samples ... transforms } onto glint's participating medium
// (shading/medium.h), its densities read as pigments are (density_map their colour map).
#include <algorithm>

#include "glint/scene/pov/pov_item_reader.h"

namespace glint {

namespace {

Color rgb_of(const PovVector& c) { return {float(c[0]), float(c[1]), float(c[2])}; }

constexpr int kMostPoints = 128;

}  // namespace

PovPigment PovItemReader::density() {
    parser_.expect("{", "after density");
    // A density without a pattern is 1 everywhere; a pattern's runs from black to white.
    PovPigment plain;
    plain.color = PovVector::of(0, 5);
    plain.color[0] = plain.color[1] = plain.color[2] = 1;
    return pigment_body(plain, "}");
}

PovMedium PovItemReader::media(const PovToken& keyword) {
    parser_.expect("{", "after " + keyword.text);
    const std::optional<PovMedium> declared = take_declared<PovMedium>();
    PovMedium m = declared ? *declared : PovMedium{};
    // POV-Ray 3.7's sampling: `intervals` stretches, `samples` points in each, and with method 3
    // up to 2^aa_level more where they differ; glint spreads as many points evenly, at most
    // kMostPoints (POV-Ray's subdivision seldom goes all the way).
    int intervals = 1, samples = 1, method = 3, aa_level = 3;
    bool sampling_given = false;
    // Each value is checked where it is written, by the medium's own ranges.
    const auto checked = [&](const PovToken& at) {
        if (const std::string problem = describe_problem(m.medium); !problem.empty())
            throw parser_.error_at(at, problem);
    };
    const auto colour = [&](const PovToken& token, Color& into) {
        const PovToken at = parser_.peek();
        into = rgb_of(parser_.color_expression("after " + token.text));
        checked(at);
    };
    for (;;) {
        const PovToken token = parser_.next();
        if (token.is_symbol("}")) break;
        const std::string& w = token.text;
        if (w == "absorption") {
            colour(token, m.medium.absorption);
        } else if (w == "emission") {
            colour(token, m.medium.emission);
        } else if (w == "scattering") {
            parser_.expect("{", "after scattering");
            const int type = parser_.whole_number("as the scattering type", 1, 5);
            // 1 isotropic, 2 Mie hazy, 3 Mie murky, 4 Rayleigh, 5 Henyey-Greenstein.
            constexpr PhaseKind kTypes[] = {PhaseKind::isotropic, PhaseKind::mie_hazy,
                                            PhaseKind::mie_murky, PhaseKind::rayleigh,
                                            PhaseKind::henyey_greenstein};
            m.medium.phase = kTypes[type - 1];
            parser_.accept(",");
            colour(token, m.medium.scattering);
            for (;;) {
                const PovToken more = parser_.next();
                if (more.is_symbol("}")) break;
                const PovToken at = parser_.peek();
                if (more.is_word("eccentricity")) {
                    m.medium.eccentricity = float(parser_.finite_float("after eccentricity"));
                    checked(at);
                } else if (more.is_word("extinction")) {
                    m.medium.extinction = float(parser_.finite_float("after extinction"));
                    checked(at);
                } else {
                    throw unsupported(more, "in scattering");
                }
            }
        } else if (w == "density") {
            m.densities.push_back(density());
        } else if (w == "method") {
            method = parser_.whole_number("after method", 1, 3);
            sampling_given = true;
        } else if (w == "intervals") {
            intervals = parser_.whole_number("after intervals", 1, 1000);
            sampling_given = true;
        } else if (w == "samples") {
            samples = parser_.whole_number("after samples", 1, 1000);
            if (parser_.accept(","))
                samples = std::max(samples, parser_.whole_number("as the most samples", 1, 1000));
            sampling_given = true;
        } else if (w == "aa_level") {
            aa_level = parser_.whole_number("after aa_level", 0, 8);
        } else if (w == "jitter" || w == "aa_threshold" || w == "confidence" || w == "variance" ||
                   w == "ratio") {
            parser_.finite_float("after " + w);  // POV-Ray's adaptive sampling's own settings
        } else if (const auto step = transform_step(token)) {
            for (PovPigment& d : m.densities) d.transform = *step * d.transform;
        } else {
            throw unsupported(token, "in media");
        }
    }
    if (sampling_given || !declared) {
        const int adaptive = method == 3 ? 1 << aa_level : 1;
        m.medium.samples = std::clamp(intervals * samples * adaptive, 1, kMostPoints);
    }
    return m;
}

}  // namespace glint
