// The ray tree as text, JSON and DOT. Text rounds to 4 significant digits for reading; JSON
// writes 9, which give back each float exactly.
#include "glint/render/explain/ray_tree_formats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "glint/math/constants.h"
#include "glint/render/json_string.h"

namespace glint {

namespace {

std::string number(float v, int digits) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", digits, double(v));
    return text;
}

std::string read(float v) { return number(v, 4); }
std::string read(Vector3 v) { return "(" + read(v.x) + ", " + read(v.y) + ", " + read(v.z) + ")"; }
std::string read(Point3 p) { return read(Vector3{p.x, p.y, p.z}); }
std::string read(Point2 p) { return "(" + read(p.x) + ", " + read(p.y) + ")"; }
std::string read(Color c) { return "(" + read(c.r) + ", " + read(c.g) + ", " + read(c.b) + ")"; }

std::string angle(float cosine) {
    return read(degrees(std::acos(std::clamp(cosine, -1.0f, 1.0f)))) + " deg";
}

std::string_view kind_name(RayKind kind) {
    switch (kind) {
        case RayKind::primary:
            return "eye";
        case RayKind::shadow:
            return "shadow";
        case RayKind::reflected:
            return "reflected";
        case RayKind::refracted:
            return "refracted";
        case RayKind::diffuse:
            return "diffuse";
        case RayKind::particle:
            return "particle";
    }
    return "?";
}

// "eye ray", "reflected ray (glossy lobe)", "refracted ray (translucency lobe)".
std::string ray_title(const RayTree& tree, const RayNode& n) {
    std::string title = std::string(kind_name(n.kind)) + " ray";
    if (n.parent < 0) return title;
    for (const BranchRecord& b : tree.nodes[std::size_t(n.parent)].branches)
        if (b.child >= 0 && &tree.nodes[std::size_t(b.child)] == &n && b.lobe_u &&
            n.kind != RayKind::diffuse)
            title += n.kind == RayKind::reflected ? " (glossy lobe)" : " (translucency lobe)";
    return title;
}

Color local(const RayNode& n) { return n.emission + n.ambient + n.direct; }

// ---- text

class TextWriter {
public:
    explicit TextWriter(const RayTree& tree) : tree_(tree) {}

    std::string write() {
        const RayTree& t = tree_;
        line(0, "pixel (" + std::to_string(t.x) + ", " + std::to_string(t.y) + "), sample " +
                    std::to_string(t.sample) + ", seed " + std::to_string(t.seed) + ", the " +
                    t.integrator + " integrator");
        std::string drawn;
        for (const RandomDraw& d : t.draws)
            drawn +=
                (drawn.empty() ? "" : ", ") + d.purpose + " " + (d.pair ? read(d.u) : read(d.u.x));
        const std::string weight =
            t.filter_weight ? ", counting for this pixel alone with the filter's weight " +
                                  read(*t.filter_weight) + " (filter importance sampling)"
                            : "";
        line(0, "lands on the film at " + read(t.film) + weight + "; numbers drawn: " + drawn);
        const Color evaluated = evaluate(t);
        const bool exact = evaluated.r == t.sample_value.r && evaluated.g == t.sample_value.g &&
                           evaluated.b == t.sample_value.b;
        line(0, "sample colour " + read(t.sample_value) +
                    (exact ? " (the tree's terms give it to the last bit)"
                           : " (the tree's terms give " + read(evaluated) + ")"));
        out_ << "\n";
        if (!t.nodes.empty()) node(0, 0);
        if (t.particles) particles(*t.particles);
        return out_.str();
    }

private:
    void particles(const ParticleReport& r) {
        out_ << "\n";
        line(0, "particles of this sample pass (the light integrator's light from the lights):");
        line(1, std::to_string(r.traced) + " sent, one by each pixel's sample; " +
                    std::to_string(r.seen) + " reached the eye somewhere on the film");
        line(1, std::to_string(r.landed) + (r.landed == 1 ? " contribution" : " contributions") +
                    " landed on this pixel, adding " + read(r.value) + "; with the eye ray's " +
                    read(tree_.sample_value) + ", the pass gives the pixel " +
                    read(r.value + tree_.sample_value));
        if (!r.largest.empty()) line(1, "the largest:");
        for (const ParticleContribution& c : r.largest) {
            const std::string path = c.bounces == 0 ? "straight"
                                     : c.bounces == 1
                                         ? "after 1 bounce"
                                         : "after " + std::to_string(c.bounces) + " bounces";
            line(2, "from " + c.light + " (sent by pixel (" + std::to_string(c.from_x) + ", " +
                        std::to_string(c.from_y) + ")), " + path + " to object " +
                        std::to_string(c.object) + " at " + read(c.point) + ": " + read(c.value) +
                        " landing at " + read(c.film) + ", weight " + read(c.weight) + " here");
        }
    }

    void line(int indent, const std::string& text) {
        out_ << std::string(std::size_t(indent) * 2, ' ') << text << "\n";
    }

    void node(int index, int indent) {
        const RayNode& n = tree_.nodes[std::size_t(index)];
        line(indent, ray_title(tree_, n) + " from " + read(n.ray.origin) + " direction " +
                         read(n.ray.direction) + ", depth " + std::to_string(n.depth) +
                         ", weight " + read(n.weight));
        const int in = indent + 1;
        const auto fog_line = [&] {
            if (n.fog && n.fog_inside && is_black(n.fog->added))
                line(in, "through the object's inside: its fade lets " +
                             read(n.fog->transmittance) + " through (brings T x what lies behind)");
            else if (n.fog && n.fog_inside)
                line(in, "through the object's inside: its fade and media let " +
                             read(n.fog->transmittance) + " through, add " + read(n.fog->added) +
                             " (bring T x what lies behind + that)");
            else if (n.fog)
                line(in, "through fog: lets " + read(n.fog->transmittance) + " through, adds " +
                             read(n.fog->added) + " (brings T x what lies behind + that)");
        };
        if (n.stop == StopReason::missed) {
            line(in, "missed everything: brings the background " + read(n.background));
            fog_line();
            line(in, "contributes " + read(contribution(n)) + " to the sample");
            return;
        }
        const std::string triangle =
            n.triangle ? ", triangle " + std::to_string(*n.triangle) : std::string();
        line(in, "hits object " + std::to_string(n.object) + " (" + n.shape + triangle +
                     "), material \"" + n.material + "\", at t = " + read(n.t));
        line(in + 1, "point " + read(n.point) + ", normal " + read(n.geometric_normal) +
                         (n.shading_normal == n.geometric_normal
                              ? ""
                              : ", shading normal " + read(n.shading_normal)) +
                         (n.entering ? ", entering (front side)" : ", leaving (back side)"));
        fog_line();
        if (n.pencil) {
            const UvFootprint& f = n.pencil->footprint;
            line(in + 1, "pencil " + read(pencil_width(*n.pencil)) + " wide: steps " +
                             read(n.pencil->dpdx) + " across, " + read(n.pencil->dpdy) +
                             " down a pixel; uv footprint (" + read(f.dudx) + ", " + read(f.dvdx) +
                             ") across, (" + read(f.dudy) + ", " + read(f.dvdy) + ") down");
        }
        if (n.path) {
            write_path_vertex(*n.path, in);
            line(in, "local term (emission + light) " + read(local(n)) + ", contributes " +
                         read(contribution(n)) + " to the sample");
        } else {
            if (n.emission != Color{}) line(in, "emission " + read(n.emission));
            line(in, "ambient ka Ia C = " + read(n.ambient));
            for (const LightRecord& light : n.lights) write_light(light, in);
            line(in, "local term (emission + ambient + lights) " + read(local(n)) +
                         ", contributes " + read(contribution(n)) + " to the sample");
        }
        if (n.stop == StopReason::max_depth) {
            line(in, n.path ? "stops: beyond the maximum depth (" + std::to_string(n.depth - 1) +
                                  "): traced for the light it meets alone"
                            : "stops: the maximum depth (" + std::to_string(n.depth) +
                                  "): no reflected or refracted ray");
        }
        if (n.stop == StopReason::roulette) line(in, "stops: Russian roulette ends the path");
        if (n.transmits) {
            std::string snell = "Snell: n1 = " + read(n.n1) + ", n2 = " + read(n.n2) +
                                ", incidence " + angle(n.cos_incident);
            snell +=
                n.total_internal_reflection
                    ? ": total internal reflection (sin of the refracted angle " +
                          read(n.n1 / n.n2 *
                               std::sqrt(std::max(0.0f, 1 - n.cos_incident * n.cos_incident))) +
                          " > 1)"
                    : ", refraction " + angle(n.cos_refracted);
            line(in, snell);
        }
        if (n.wavelength)
            line(in, "dispersion: the refracted ray takes wavelength " + read(*n.wavelength) +
                         " nm (drawn from " + read(*n.wavelength_u) + ")");
        for (const BranchRecord& b : n.branches) {
            if (n.path && n.path->scattered) break;  // the path's one ray is told above
            std::string text = std::string(kind_name(b.kind)) +
                               (b.kind == RayKind::reflected ? ": kr = " : ": kt = ") + read(b.k);
            if (b.lobe_u) text += ", lobe drawn from " + read(*b.lobe_u);
            if (b.survival < 1)
                text += ", Russian roulette traces it with probability " + read(b.survival);
            if (b.stop == StopReason::none) {
                text += ", traced";
                if (b.factor != Color::gray(b.k)) text += ", its colour times " + read(b.factor);
            } else if (b.stop == StopReason::min_weight) {
                text +=
                    ", not traced: weight " + read(n.weight * b.k) + " is below the minimum weight";
            } else {
                text += ", not traced: " + std::string(stop_reason_name(b.stop));
            }
            line(in, text);
        }
        line(in, "colour " + read(n.value));
        for (const BranchRecord& b : n.branches)
            if (b.child >= 0) node(b.child, in);
    }

    void write_path_vertex(const PathVertexRecord& v, int indent) {
        if (v.le != Color{}) {
            std::string why;
            if (v.emission_weight == 0)
                why = " (it glows but lights nothing: an area light's face, or emits_light off)";
            else if (v.emission_bsdf_pdf == 0)
                why = " (seen by the eye, or through a mirror or clear glass)";
            else if (v.emission_light_pdf == 0)
                why = " (no shadow ray aims at it)";
            else
                why = " (the power heuristic of the scattered direction's BSDF pdf " +
                      read(v.emission_bsdf_pdf) + " against its light pdf " +
                      read(v.emission_light_pdf) + ")";
            line(indent, "emits Le " + read(v.le) + ", counted with weight " +
                             read(v.emission_weight) + why);
        }
        for (const NextEventRecord& e : v.next_events) {
            const std::string picked = e.pick == 1 && v.next_events.size() > 1
                                           ? " (every light is sampled)"
                                           : ", picked with probability " + read(e.pick);
            line(indent, "next event: " + e.light + picked + ": L " + read(e.to_light) +
                             ", distance " + read(e.distance) + ", irradiance facing it pi IL " +
                             read(e.irradiance));
            std::string numbers = "BSDF f " + read(e.f) + ", |N.L| = " + read(e.cosine) +
                                  ", BSDF pdf " + read(e.bsdf_pdf);
            if (e.light_pdf > 0)
                numbers += ", light pdf " + read(e.pick) + " x " + read(e.light_pdf) +
                           ", MIS weight " + read(e.mis);
            if (e.f == Color{})
                numbers += ": the BSDF sends nothing that way, no feeler";
            else
                numbers +=
                    is_black(e.shadow) ? ", shadow feeler blocked" : ", shadow feeler unblocked";
            line(indent + 1, numbers + "; adds " + read(e.term));
        }
        if (v.photons >= 0)
            line(indent, "photon map: " + std::to_string(v.photons) +
                             " photons within r = " + read(v.gather_radius) +
                             ", the sum of f power / (pi r^2 photons emitted) adds " +
                             read(v.photon_term));
        if (v.scattered) {
            std::string text = "scatters by the " + v.lobe + " part: direction " + read(v.wi);
            text += v.delta ? ", a delta part picked with probability " + read(v.scatter_pdf)
                            : ", f " + read(v.scatter_f) + ", pdf " + read(v.scatter_pdf);
            text += ", weight f |N.wi| / pdf " + read(v.weight);
            if (v.survival < 1)
                text += ", Russian roulette lets it go on with probability " + read(v.survival);
            line(indent, text);
        }
    }

    void write_light(const LightRecord& light, int indent) {
        if (!light.averaged) {
            write_sample(light.name + ": ", light.samples.at(0), indent);
            return;
        }
        line(indent, light.name + ": the mean of " + std::to_string(light.samples.size()) +
                         " samples, " + read(light.value));
        for (const LightSampleRecord& s : light.samples)
            write_sample("sample " + std::to_string(s.index) + " drawn from " + read(*s.u) + ": ",
                         s, indent + 1);
    }

    void write_sample(const std::string& title, const LightSampleRecord& s, int indent) {
        std::string text = title + "L " + read(s.to_light) + ", distance " + read(s.distance) +
                           ", N.L = " + read(s.n_dot_l);
        if (!s.faces_light) {
            line(indent, text + (s.n_dot_l <= 0 ? ": behind the surface, no feeler, adds nothing"
                                                : ": sends nothing this way, adds nothing"));
            return;
        }
        if (s.shadow_map) {
            // A map's answer is grey.
            const float lit = s.shadow.r;
            text += lit == 0  ? ", in shadow by the shadow map"
                    : lit < 1 ? ", " + read(lit) + " of it lit by the shadow map's filter"
                              : ", lit by the shadow map";
            if (lit == 0 && s.occluder)
                text += " (object " + std::to_string(*s.occluder) + " on the feeler's line)";
            if (lit == 0) {
                line(indent, text + ": adds nothing");
                return;
            }
            line(indent, text + ", IL " + read(s.intensity));
        } else if (is_black(s.shadow)) {
            text += ", shadow feeler blocked";
            if (s.occluder) text += " by object " + std::to_string(*s.occluder);
            line(indent, text + ": adds nothing");
            return;
        } else {
            text += s.shadow != Color{1, 1, 1}
                        ? ", " + read(s.shadow) + " of it through transparent objects"
                        : ", shadow feeler unblocked";
            line(indent, text + ", IL " + read(s.intensity));
        }
        const std::string spec = s.blinn ? "(H.N)^n" : "(R.V)^n";
        const std::string cosine = s.brilliance == 1 ? "(N.L)" : "(N.L)^" + read(s.brilliance);
        const std::string tint = s.metallic == 0 ? "" : " S(metallic " + read(s.metallic) + ")";
        line(indent + 1, "diffuse kd C " + cosine + " IL " + read(s.diffuse) + ", highlight ks" +
                             tint + " " + spec + " IL " + read(s.highlight) +
                             (s.blinn ? " with H.N = " : " with R.V = ") +
                             read(s.highlight_cosine) + "; adds " + read(s.term));
    }

    const RayTree& tree_;
    std::ostringstream out_;
};

// ---- JSON

std::string exact(float v) {
    if (std::isinf(v)) return v > 0 ? "\"inf\"" : "\"-inf\"";
    if (std::isnan(v)) return "\"nan\"";
    return number(v, 9);
}
std::string exact(Vector3 v) {
    return "[" + exact(v.x) + ", " + exact(v.y) + ", " + exact(v.z) + "]";
}
std::string exact(Point3 p) { return exact(Vector3{p.x, p.y, p.z}); }
std::string exact(Point2 p) { return "[" + exact(p.x) + ", " + exact(p.y) + "]"; }
std::string exact(Color c) {
    return "[" + exact(c.r) + ", " + exact(c.g) + ", " + exact(c.b) + "]";
}

// Fields of one JSON object, written as "key": value.
class Fields {
public:
    Fields& add(std::string_view key, const std::string& value) {
        text_ += (text_.empty() ? "" : ", ") + json_string(key) + ": " + value;
        return *this;
    }
    std::string object() const { return "{" + text_ + "}"; }

private:
    std::string text_;
};

template <class T, class F>
std::string array(const std::vector<T>& items, const F& write) {
    std::string text = "[";
    for (std::size_t i = 0; i < items.size(); ++i) text += (i ? ", " : "") + write(items[i]);
    return text + "]";
}

std::string light_sample_json(const LightSampleRecord& s) {
    Fields f;
    f.add("index", std::to_string(s.index)).add("u", s.u ? exact(*s.u) : "null");
    f.add("to_light", exact(s.to_light)).add("distance", exact(s.distance));
    f.add("intensity", exact(s.intensity)).add("n_dot_l", exact(s.n_dot_l));
    f.add("faces_light", s.faces_light ? "true" : "false").add("shadow", exact(s.shadow));
    f.add("shadow_map", s.shadow_map ? "true" : "false");
    f.add("occluder", s.occluder ? std::to_string(*s.occluder) : "null");
    f.add("highlight_model", s.blinn ? "\"blinn\"" : "\"phong\"");
    f.add("highlight_vector", exact(s.highlight_vector));
    f.add("highlight_cosine", exact(s.highlight_cosine));
    f.add("brilliance", exact(s.brilliance)).add("metallic", exact(s.metallic));
    f.add("diffuse", exact(s.diffuse)).add("highlight", exact(s.highlight));
    return f.add("term", exact(s.term)).object();
}

std::string light_json(const LightRecord& light) {
    Fields f;
    f.add("name", json_string(light.name)).add("light", std::to_string(light.light));
    f.add("object_light", light.object_light ? "true" : "false");
    f.add("averaged", light.averaged ? "true" : "false");
    f.add("samples", array(light.samples, light_sample_json));
    return f.add("value", exact(light.value)).object();
}

std::string branch_json(const BranchRecord& b) {
    Fields f;
    f.add("kind", json_string(kind_name(b.kind)))
        .add("k", exact(b.k))
        .add("factor", exact(b.factor));
    f.add("lobe_u", b.lobe_u ? exact(*b.lobe_u) : "null");
    f.add("stop", b.stop == StopReason::none ? "null" : json_string(stop_reason_name(b.stop)));
    f.add("survival", exact(b.survival));
    return f.add("child", b.child >= 0 ? std::to_string(b.child) : "null").object();
}

std::string path_json(const PathVertexRecord& v) {
    Fields f;
    f.add("le", exact(v.le)).add("emission_weight", exact(v.emission_weight));
    f.add("emission_bsdf_pdf", exact(v.emission_bsdf_pdf));
    f.add("emission_light_pdf", exact(v.emission_light_pdf));
    std::string next_events;
    for (const NextEventRecord& e : v.next_events) {
        Fields light;
        light.add("light", json_string(e.light)).add("pick", exact(e.pick));
        light.add("to_light", exact(e.to_light)).add("distance", exact(e.distance));
        light.add("irradiance", exact(e.irradiance)).add("f", exact(e.f));
        light.add("cosine", exact(e.cosine)).add("light_pdf", exact(e.light_pdf));
        light.add("bsdf_pdf", exact(e.bsdf_pdf)).add("mis", exact(e.mis));
        light.add("shadow", exact(e.shadow)).add("term", exact(e.term));
        next_events += (next_events.empty() ? "" : ", ") + light.object();
    }
    f.add("next_event", "[" + next_events + "]");
    if (v.photons >= 0) {
        Fields photons;
        photons.add("found", std::to_string(v.photons)).add("radius", exact(v.gather_radius));
        f.add("photons", photons.add("term", exact(v.photon_term)).object());
    } else {
        f.add("photons", "null");
    }
    if (v.scattered) {
        Fields scatter;
        scatter.add("lobe", json_string(v.lobe)).add("wi", exact(v.wi));
        scatter.add("f", exact(v.scatter_f)).add("pdf", exact(v.scatter_pdf));
        scatter.add("delta", v.delta ? "true" : "false").add("weight", exact(v.weight));
        scatter.add("survival", exact(v.survival));
        f.add("scattered", scatter.object());
    } else {
        f.add("scattered", "null");
    }
    return f.object();
}

std::string node_json(const RayTree& tree, int index) {
    const RayNode& n = tree.nodes[std::size_t(index)];
    Fields f;
    f.add("id", std::to_string(index)).add("kind", json_string(kind_name(n.kind)));
    f.add("parent", n.parent >= 0 ? std::to_string(n.parent) : "null");
    f.add("depth", std::to_string(n.depth)).add("weight", exact(n.weight));
    f.add("throughput", exact(n.throughput));
    f.add("origin", exact(n.ray.origin)).add("direction", exact(n.ray.direction));
    f.add("time", exact(n.ray.time));
    f.add("stop", n.stop == StopReason::none ? "null" : json_string(stop_reason_name(n.stop)));
    if (n.fog) {
        Fields fog;
        fog.add("transmittance", exact(n.fog->transmittance)).add("added", exact(n.fog->added));
        fog.add("inside", n.fog_inside ? "true" : "false");
        f.add("fog", fog.object());
    } else {
        f.add("fog", "null");
    }
    if (n.stop == StopReason::missed) {
        f.add("hit", "null").add("background", exact(n.background));
    } else {
        Fields hit;
        hit.add("t", exact(n.t)).add("object", std::to_string(n.object));
        hit.add("triangle", n.triangle ? std::to_string(*n.triangle) : "null");
        hit.add("shape", json_string(n.shape)).add("material", json_string(n.material));
        hit.add("point", exact(n.point)).add("geometric_normal", exact(n.geometric_normal));
        hit.add("shading_normal", exact(n.shading_normal));
        hit.add("entering", n.entering ? "true" : "false");
        if (n.pencil) {
            const UvFootprint& fp = n.pencil->footprint;
            Fields pencil;
            pencil.add("width", exact(pencil_width(*n.pencil)));
            pencil.add("dpdx", exact(n.pencil->dpdx)).add("dpdy", exact(n.pencil->dpdy));
            pencil.add("footprint", "[" + exact(fp.dudx) + ", " + exact(fp.dvdx) + ", " +
                                        exact(fp.dudy) + ", " + exact(fp.dvdy) + "]");
            hit.add("pencil", pencil.object());
        } else {
            hit.add("pencil", "null");
        }
        f.add("hit", hit.object());
        f.add("emission", exact(n.emission)).add("ambient", exact(n.ambient));
        f.add("lights", array(n.lights, light_json)).add("direct", exact(n.direct));
        if (n.transmits) {
            Fields snell;
            snell.add("n1", exact(n.n1)).add("n2", exact(n.n2));
            snell.add("cos_incident", exact(n.cos_incident));
            snell.add("cos_refracted",
                      n.total_internal_reflection ? "null" : exact(n.cos_refracted));
            snell.add("total_internal_reflection", n.total_internal_reflection ? "true" : "false");
            f.add("snell", snell.object());
        } else {
            f.add("snell", "null");
        }
        f.add("wavelength", n.wavelength ? exact(*n.wavelength) : "null");
        f.add("wavelength_u", n.wavelength_u ? exact(*n.wavelength_u) : "null");
        f.add("branches", array(n.branches, branch_json));
        f.add("path", n.path ? path_json(*n.path) : "null");
    }
    f.add("contribution", exact(contribution(n)));
    return f.add("value", exact(n.value)).object();
}

// ---- DOT

// A quoted DOT label; a line break in the text starts a new line of the label.
std::string dot_label(const std::string& text) {
    std::string escaped;
    for (const char c : text) {
        if (c == '\n') {
            escaped += "\\n";
            continue;
        }
        if (c == '"' || c == '\\') escaped += '\\';
        escaped += c;
    }
    return "\"" + escaped + "\"";
}

}  // namespace

std::string ray_tree_text(const RayTree& tree) { return TextWriter(tree).write(); }

std::string ray_tree_json(const RayTree& tree) {
    Fields f;
    f.add("format", json_string("glint-ray-tree")).add("version", "1");
    f.add("pixel", "[" + std::to_string(tree.x) + ", " + std::to_string(tree.y) + "]");
    f.add("sample", std::to_string(tree.sample)).add("seed", std::to_string(tree.seed));
    f.add("integrator", json_string(tree.integrator)).add("film", exact(tree.film));
    if (tree.filter_weight) f.add("filter_weight", exact(*tree.filter_weight));
    f.add("draws", array(tree.draws, [](const RandomDraw& d) {
              Fields draw;
              draw.add("purpose", json_string(d.purpose))
                  .add("dimension", std::to_string(d.dimension));
              return draw.add("u", d.pair ? exact(d.u) : "[" + exact(d.u.x) + "]").object();
          }));
    f.add("sample_value", exact(tree.sample_value)).add("evaluated", exact(evaluate(tree)));
    std::string rays = "[\n";
    for (std::size_t i = 0; i < tree.nodes.size(); ++i)
        rays += "  " + node_json(tree, int(i)) + (i + 1 < tree.nodes.size() ? ",\n" : "\n");
    f.add("rays", rays + "]");
    if (const auto& r = tree.particles) {
        Fields p;
        p.add("traced", std::to_string(r->traced)).add("seen", std::to_string(r->seen));
        p.add("landed", std::to_string(r->landed)).add("value", exact(r->value));
        p.add("largest", array(r->largest, [](const ParticleContribution& c) {
                  Fields one;
                  one.add("from_pixel",
                          "[" + std::to_string(c.from_x) + ", " + std::to_string(c.from_y) + "]");
                  one.add("light", json_string(c.light)).add("emitter", std::to_string(c.emitter));
                  one.add("bounces", std::to_string(c.bounces))
                      .add("object", std::to_string(c.object));
                  one.add("point", exact(c.point)).add("film", exact(c.film));
                  return one.add("value", exact(c.value)).add("weight", exact(c.weight)).object();
              }));
        f.add("particles", p.object());
    }
    return f.object() + "\n";
}

std::string ray_tree_dot(const RayTree& tree) {
    std::ostringstream out;
    out << "digraph ray_tree {\n  rankdir=TB;\n  node [shape=box, fontname=\"Helvetica\"];\n";
    out << "  label="
        << dot_label("pixel (" + std::to_string(tree.x) + ", " + std::to_string(tree.y) +
                     "), sample " + std::to_string(tree.sample) + ": " + read(tree.sample_value))
        << ";\n";
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        const RayNode& n = tree.nodes[i];
        std::string label = ray_title(tree, n) + "\n";
        if (n.stop == StopReason::missed) {
            label += "missed: background " + read(n.background);
        } else {
            label += n.shape + " " + std::to_string(n.object) + ", \"" + n.material +
                     "\"\nt = " + read(n.t) + ", local " + read(local(n));
            if (n.stop == StopReason::max_depth) label += "\nmaximum depth";
        }
        label += "\ncolour " + read(n.value);
        out << "  ray" << i << " [label=" << dot_label(label) << "];\n";
        for (std::size_t l = 0; l < n.lights.size(); ++l) {
            const LightRecord& light = n.lights[l];
            int lit = 0;
            for (const LightSampleRecord& s : light.samples)
                lit += s.faces_light && !is_black(s.shadow);
            out << "  ray" << i << "_light" << l << " [shape=ellipse, style=dashed, label="
                << dot_label(light.name + "\n" + std::to_string(lit) + " of " +
                             std::to_string(light.samples.size()) + " lit, " + read(light.value))
                << "];\n";
            out << "  ray" << i << " -> ray" << i << "_light" << l
                << " [style=dashed, arrowhead=none];\n";
        }
        for (std::size_t b = 0; b < n.branches.size(); ++b) {
            const BranchRecord& branch = n.branches[b];
            const std::string k = std::string(kind_name(branch.kind)) + " " + read(branch.k);
            if (branch.child >= 0) {
                out << "  ray" << i << " -> ray" << branch.child << " [label=" << dot_label(k)
                    << "];\n";
            } else {
                out << "  ray" << i << "_cut" << b << " [shape=plaintext, label="
                    << dot_label(std::string(stop_reason_name(branch.stop))) << "];\n";
                out << "  ray" << i << " -> ray" << i << "_cut" << b
                    << " [style=dotted, label=" << dot_label(k) << "];\n";
            }
        }
    }
    out << "}\n";
    return out.str();
}

}  // namespace glint
