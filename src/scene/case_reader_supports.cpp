// [supports]: free, clamped (clamp zones) or chucks (body, expanding
// elements, interface, bearing) (scene/case_reader.hpp).
#include "scene/case_reader.hpp"

#include "common/error.hpp"
#include "scene/chuck_contact.hpp"

#include <cmath>
#include <limits>
#include <cstring>

namespace coremodal::case_reading {

SupportSpec CaseReader::read_supports(const Section& top, Scene& scene) const {
    SupportSpec spec;
    const double core_length = scene.core.length;
    const std::optional<Section> supports = section(top, "supports", "supports");
    if (!supports) return spec;
    // The type decides the schema of [supports.left] and [supports.right].
    const std::string type = choice(*supports, "type", kSupportTypes).value_or("free");
    const std::string end_schema = type == "chucks" ? "chuck" : "clamp";
    const std::optional<Section> left = section(*supports, "left", end_schema);
    const std::optional<Section> right = section(*supports, "right", end_schema);
    if (type == "free") {
        if (left || right)
            fail((left ? left : right)->table->source(),
                 (left ? left : right)->display +
                     " is given but [supports] type is \"free\"; "
                     "expected type = \"clamped\" or \"chucks\", or remove the table");
        return spec;
    }
    if (type == "chucks") return read_chucks(*supports, left, right, scene);
    spec.kind = SupportKind::clamped;
    if (!left)
        fail(supports->table->source(),
             "[supports] type = \"clamped\" needs [supports.left]; expected e.g. "
             "[supports.left] length = \"70 mm\" (right mirrors left unless given)");
    const ClampInput left_in = read_clamp(*left);
    const ClampInput right_in = right ? read_clamp(*right) : left_in;
    spec.clamps.push_back(place_clamp("left", left_in, core_length, false));
    spec.clamps.push_back(place_clamp("right", right_in, core_length, true));
    check_no_overlap(spec.clamps[0], spec.clamps[1], right ? right_in.where : left_in.where);
    return spec;
}

SupportSpec CaseReader::read_chucks(const Section& supports, const std::optional<Section>& left,
                                    const std::optional<Section>& right, Scene& scene) const {
    if (!left)
        fail(supports.table->source(),
             "[supports] type = \"chucks\" needs [supports.left]; expected e.g. [supports.left] "
             "inserted_length = \"110 mm\" with [[supports.left.expanding]] center = \"70 mm\" "
             "width = \"40 mm\" (right mirrors left unless given)");
    SupportSpec spec;
    spec.kind = SupportKind::chucks;
    spec.chucks.push_back(read_chuck(*left, "left", scene));
    if (right) {
        spec.chucks.push_back(read_chuck(*right, "right", scene));
    } else {
        ChuckSpec mirrored = spec.chucks.front();
        mirrored.name = "right";
        spec.chucks.push_back(mirrored);
    }
    return spec;
}

ChuckSpec CaseReader::read_chuck(const Section& s, std::string name, Scene& scene) const {
    ChuckSpec c;
    c.name = std::move(name);
    const double bore = scene.core.inner_diameter, length = scene.core.length;
    c.inserted_length = required(s, "inserted_length",
                                 "the chuck length inside the core, e.g. inserted_length = \"110 mm\"");
    if (c.inserted_length > length / 2)
        fail(*get(s, "inserted_length"),
             echo(s, "inserted_length", *get(s, "inserted_length")) + " is longer than half the core ([core] "
             "length = " + format_quantity(length, Dimension::length) +
             "); expected the two chucks not to meet, inserted_length <= " +
             format_quantity(length / 2, Dimension::length));
    at_most_one(s, "clearance", "body_diameter");
    if (const auto d = quantity(s, "body_diameter")) {
        c.body_diameter = *d;
        if (c.body_diameter > bore)
            fail(*get(s, "body_diameter"),
                 echo(s, "body_diameter", *get(s, "body_diameter")) + " is larger than the core bore "
                 "([core] inner_diameter = " + format_quantity(bore, Dimension::length) +
                 "); expected a chuck body that fits inside the core (at most the bore: zero clearance)");
    } else {
        const double clearance = quantity(s, "clearance").value_or(kDefaultChuckClearance);
        if (!get(s, "clearance"))
            scene.assumptions.push_back("chuck " + c.name + ": radial clearance " +
                                        format_quantity(kDefaultChuckClearance, Dimension::length) +
                                        " assumed (body diameter = bore - 2 x clearance)");
        c.body_diameter = bore - 2 * clearance;
        if (c.body_diameter <= 0.2 * bore) {
            // Without a clearance of its own the default leaves no body: the bore itself is implausible.
            if (!get(s, "clearance"))
                fail(*s.table, "the default radial clearance " +
                                   format_quantity(kDefaultChuckClearance, Dimension::length) +
                                   " leaves no chuck body in a core bore of " + format_quantity(bore, Dimension::length) +
                                   " ([core] inner_diameter); expected a core bore of tens of millimetres or a "
                                   "smaller clearance or body_diameter in " + s.display);
            fail(*get(s, "clearance"), echo(s, "clearance", *get(s, "clearance")) +
                                           " leaves no chuck body; expected a radial clearance of "
                                           "a fraction of a millimetre to a few millimetres");
        }
    }
    c.shaft_diameter = quantity(s, "shaft_diameter").value_or(c.body_diameter);
    // The shaft leaves the body's end face: it cannot be wider than the body.
    if (c.shaft_diameter > c.body_diameter * (1 + 1e-9))
        fail(*get(s, "shaft_diameter"),
             echo(s, "shaft_diameter", *get(s, "shaft_diameter")) + " is wider than the chuck body (" +
                 format_quantity(c.body_diameter, Dimension::length) +
                 "); expected at most the body diameter (the shaft leaves the body's end face)");
    if (!get(s, "shaft_diameter"))
        scene.assumptions.push_back("chuck " + c.name + ": shaft diameter = chuck body diameter (" +
                                    format_quantity(c.body_diameter, Dimension::length) + ") assumed");
    c.shaft_length = quantity(s, "shaft_length").value_or(kDefaultShaftLength);
    if (!get(s, "shaft_length"))
        scene.assumptions.push_back("chuck " + c.name + ": shaft length (core end to bearing) " +
                                    format_quantity(kDefaultShaftLength, Dimension::length) + " assumed");
    c.material = read_material(s, "chuck " + c.name, kDefaultChuckMaterial, scene);
    c.expanding = read_expanding(s, c);
    c.interface = read_interface(s, c.name, scene);
    c.bearing = read_bearing(s, c.name, scene);
    return c;
}

std::vector<ExpandingElement> CaseReader::read_expanding(const Section& chuck, const ChuckSpec& c) const {
    const toml::node* node = get(chuck, "expanding");
    if (!node)
        fail(chuck.table->source(),
             chuck.display + " has no expanding elements; expected at least one, e.g. [[" +
                 chuck.display.substr(1, chuck.display.size() - 2) +
                 ".expanding]] center = \"70 mm\" width = \"40 mm\"");
    std::vector<ExpandingElement> out;
    const toml::array& items = *node->as_array();
    for (size_t i = 0; i < items.size(); ++i) {
        const std::string display = chuck.display.substr(0, chuck.display.size() - 1) + ".expanding #" +
                                    std::to_string(i + 1) + "]";
        const Section e = open(*items[i].as_table(), display, "expanding");
        ExpandingElement x;
        x.center = required(e, "center", "the element's axial centre from the core end, e.g. center = \"70 mm\"");
        x.width = required(e, "width", "the element's axial width, e.g. width = \"40 mm\"");
        const double near = x.center - x.width / 2, far = x.center + x.width / 2;
        if (near < -1e-12 || far > c.inserted_length + 1e-12)
            fail(*get(e, "center"),
                 display + " spans " + format_quantity(near, Dimension::length) + " to " +
                     format_quantity(far, Dimension::length) + " from the core end, outside the inserted "
                     "length 0 to " + format_quantity(c.inserted_length, Dimension::length) +
                     "; expected the element on the chuck body inside the core");
        if (const auto n = integer(e, "segments")) {
            x.segments = *n;
            x.segment_angle = required(e, "segment_angle",
                                       "the angle each segment spans, e.g. segment_angle = \"60 deg\"");
            if (x.segments * x.segment_angle > 2 * M_PI + 1e-9)
                fail(*get(e, "segment_angle"),
                     display + " " + std::to_string(x.segments) + " segments of " +
                         format_quantity(x.segment_angle * 180 / M_PI, Dimension::dimensionless) +
                         " deg overlap (more than 360 deg in all); expected segments x segment_angle <= 360 deg");
        } else if (const toml::node* a = get(e, "segment_angle")) {
            fail(*a, echo(e, "segment_angle", *a) + " without segments; expected segments = N as well, "
                                                    "or neither for a full band");
        }
        for (const ExpandingElement& other : out)
            if (std::abs(other.center - x.center) < (other.width + x.width) / 2)
                fail(*get(e, "center"), display + " overlaps an earlier expanding element of the same chuck; "
                                                  "expected separate elements");
        out.push_back(x);
    }
    return out;
}

// contact = "one-sided" (the default when not expanded) or "uniform"; a
// one-sided contact only for a chuck that was not expanded: an expanded
// element presses on the bore all around.
ContactKind CaseReader::read_contact(const Section& s, bool expanded) const {
    const std::optional<std::string> given = choice(s, "contact", kContactKinds);
    if (!given) return expanded ? ContactKind::uniform : ContactKind::one_sided;
    if (*given == "one-sided" && expanded)
        fail(*get(s, "contact"), s.display + " contact = \"one-sided\" with an expanded chuck: expanding elements "
                                             "press on the bore all around; expected expanded = false, or "
                                             "contact = \"uniform\"");
    return *given == "one-sided" ? ContactKind::one_sided : ContactKind::uniform;
}

ChuckInterface CaseReader::read_interface(const Section& s, const std::string& chuck, Scene& scene) const {
    ChuckInterface f;
    const std::string kind = choice(s, "interface", kInterfaceKinds).value_or("spring");
    f.kind = kind == "bonded" ? InterfaceKind::bonded : InterfaceKind::spring;
    if (const toml::node* e = get(s, "expanded")) f.expanded = *e->value<bool>();
    const toml::node* kn = get(s, "normal_stiffness");
    const toml::node* kt = get(s, "tangential_stiffness");
    const toml::node* p = get(s, "expansion_pressure");
    if (f.kind == InterfaceKind::bonded) {
        for (const toml::node* n : {kn, kt, p, get(s, "expanded"), get(s, "contact")})
            if (n)
                fail(*n, s.display + " interface = \"bonded\" takes no stiffness, pressure, expanded state or "
                                     "contact; expected interface = \"spring\" for a compliant contact");
        return f;
    }
    if (p && kn)
        fail(*p, s.display + " gives both expansion_pressure and normal_stiffness; expected one of them "
                             "(the pressure is converted to a stiffness, docs/theory/chucks.md)");
    if (p && !f.expanded)
        fail(*p, s.display + " expansion_pressure with expanded = false; expected no pressure for a chuck that "
                             "was not expanded");
    f.contact = read_contact(s, f.expanded);
    const bool one_sided = f.contact == ContactKind::one_sided;
    const ContactLaw& law = contact_law();
    if (kn) {
        f.normal_stiffness = *quantity(s, "normal_stiffness");
        check_not_beyond_rigid(s, "normal_stiffness", f.normal_stiffness, scene.core);
    } else {
        const double pressure = !f.expanded ? 0.0 : quantity(s, "expansion_pressure").value_or(law.default_pressure);
        if (f.expanded) f.expansion_pressure = pressure;
        f.normal_stiffness = contact_normal_stiffness(pressure, law);
        const std::string k2_h = ": k_n = K2 (p + " + std::string(one_sided ? "K1" : "p_res") + ") / h with K2 = " +
                                 format_quantity(law.stack_exponent, Dimension::dimensionless) +
                                 ", h = " + format_quantity(law.layer_thickness, Dimension::length) + " (docs/theory/chucks.md)";
        const std::string from =
            f.expanded ? "expansion pressure " + format_quantity(pressure, Dimension::pressure) + (p ? "" : " (assumed)")
            : one_sided ? "zero contact pressure (Pfeiffer's K1 = " + format_quantity(law.residual_pressure, Dimension::pressure) +
                              "), rising with the static contact pressure where the contact closes"
                        : "a chuck not expanded (residual contact pressure " +
                              format_quantity(law.residual_pressure, Dimension::pressure) + ")";
        scene.assumptions.push_back("chuck " + chuck + ": interface normal stiffness " +
                                    format_quantity(f.normal_stiffness, Dimension::stiffness_per_area) + " from " +
                                    from + k2_h);
    }
    if (kt) {
        f.tangential_stiffness = *quantity(s, "tangential_stiffness");
        check_not_beyond_rigid(s, "tangential_stiffness", f.tangential_stiffness, scene.core);
    } else {
        f.tangential_stiffness = contact_tangential_ratio(law) * f.normal_stiffness;
        scene.assumptions.push_back("chuck " + chuck + ": interface tangential stiffness " +
                                    format_quantity(f.tangential_stiffness, Dimension::stiffness_per_area) +
                                    " = Mindlin's ratio 2(1-nu)/(2-nu) with nu = 0.3 times the normal stiffness");
    }
    if (one_sided) scene.assumptions.push_back(one_sided_contact_assumption(chuck));
    return f;
}

namespace {

// Beyond rigid. A spring k in series with a roll of stiffness k_roll holds it
// as a rigid support would to k_roll / k: at k = 1e12 k_roll to 1e-12, far
// below any tolerance a run reports. A stiffer spring adds nothing to the
// physics and takes digits from the solve: the eigenvalues of a symmetric
// K, M are computed to about eps ||K|| (Golub and Van Loan, Matrix
// Computations, 4th ed., 2013, section 8.1.2, Weyl's theorem; eps = 2.2e-16),
// so a spring 1e12 times the roll's stiffness leaves the roll's own
// eigenvalues about four digits, and 1e300 none (issue 33: residual inf).
constexpr double kBeyondRigid = 1e12;

// The roll's own stiffness of the kind a spring of dimension `d` has, from
// its core (the part every support holds): for a force per displacement its
// axial E_z A / L (its stiffest deformation as a whole: bending and shear
// are softer), for a moment per rotation E_z I / L, per unit area of a layer
// on the bore E_r / wall, per unit length of a line on its surface
// E_z A / L^2.
double roll_stiffness(const CoreSpec& core, Dimension d) {
    const double ro = core.outer_diameter / 2, ri = core.inner_diameter / 2, L = core.length;
    const double area = M_PI * (ro * ro - ri * ri), inertia = M_PI / 4 * (std::pow(ro, 4) - std::pow(ri, 4));
    const double E_z = core.material.E_z;
    switch (d) {
        case Dimension::stiffness: return E_z * area / L;
        case Dimension::rotational_stiffness: return E_z * inertia / L;
        case Dimension::stiffness_per_area: return core.material.E_r / (ro - ri);
        default: return E_z * area / (L * L);  // a line spring, N/m per m of roll
    }
}

}  // namespace

double beyond_rigid(const CoreSpec& core, Dimension d) {
    const double roll = roll_stiffness(core, d);
    return roll > 0 ? kBeyondRigid * roll : std::numeric_limits<double>::infinity();
}

std::string beyond_rigid_reason(const CoreSpec& core, Dimension d) {
    const bool spring = d == Dimension::stiffness || d == Dimension::rotational_stiffness || d == Dimension::stiffness_per_area;
    const char* how = d == Dimension::stiffness              ? "axial E_z A / L"
                      : d == Dimension::rotational_stiffness ? "E_z I / L"
                      : d == Dimension::stiffness_per_area   ? "wall's E_r / wall"
                                                             : "E_z A / L^2 per unit length";
    return "the roll's own " +
           format_quantity(roll_stiffness(core, d), spring ? d : Dimension::pressure) + " (its core's " + how + ")";
}

void CaseReader::check_not_beyond_rigid(const Section& s, std::string_view key, double stiffness,
                                        const CoreSpec& core) const {
    const Dimension d = find_key(s.schema, key)->dimension;
    const double limit = beyond_rigid(core, d);
    // The mirror image: a spring 1e12 times softer than the roll holds it as
    // nothing would to 1e-12; its rigid-body motions then sit below the
    // solvers' rigid line (eigensolve/tolerances.hpp) and f1 comes out 0.
    const double loosest = limit / (kBeyondRigid * kBeyondRigid);
    const std::string what = echo(s, key, *get(s, key));
    if (stiffness < loosest)
        fail(*get(s, key), what + " is beyond loose for this roll: less than 1e-12 times " + beyond_rigid_reason(core, d) +
                               ", so it holds the roll no more than nothing would (to 1e-12); expected at least " +
                               format_quantity(loosest, d) + ", or no support there");
    if (stiffness <= limit) return;
    fail(*get(s, key), what + " is beyond rigid for this roll: more than 1e12 times " + beyond_rigid_reason(core, d) +
                           ", so it holds the roll as a rigid support would (to 1e-12) and a stiffer spring only "
                           "costs the solve its precision; expected at most " + format_quantity(limit, d) +
                           (d == Dimension::stiffness_per_area
                                ? ", or interface = \"bonded\" for a chuck that does not slip or give"
                                : ", or a rigid bearing (type = \"rigid\") for a support that does not give"));
}

BearingSpec CaseReader::read_bearing(const Section& chuck, const std::string& name, Scene& scene) const {
    BearingSpec b;
    const std::optional<Section> s = section(chuck, "bearing", "bearing");
    if (!s) {
        scene.assumptions.push_back("chuck " + name + ": no [bearing] given: rigid bearing (shaft end held)");
        return b;
    }
    const std::string type = choice(*s, "type", kBearingTypes).value_or(get(*s, "radial_stiffness") ? "elastic" : "rigid");
    if (type == "rigid") {
        for (std::string_view key : {"radial_stiffness", "tilting_stiffness", "frame_mass", "frame_stiffness"})
            if (const toml::node* n = get(*s, key))
                fail(*n, echo(*s, key, *n) + " with a rigid bearing; expected type = \"elastic\" for springs");
        return b;
    }
    b.rigid = false;
    b.radial_stiffness = required(*s, "radial_stiffness", "the bearing's radial stiffness, e.g. radial_stiffness = \"200 kN/mm\"");
    b.tilting_stiffness = required(*s, "tilting_stiffness",
                                   "the bearing's tilting stiffness, e.g. tilting_stiffness = \"1 MN*m/rad\"");
    b.frame_mass = quantity(*s, "frame_mass");
    b.frame_stiffness = quantity(*s, "frame_stiffness");
    check_not_beyond_rigid(*s, "radial_stiffness", b.radial_stiffness, scene.core);
    check_not_beyond_rigid(*s, "tilting_stiffness", b.tilting_stiffness, scene.core);
    if (b.frame_stiffness) check_not_beyond_rigid(*s, "frame_stiffness", *b.frame_stiffness, scene.core);
    if (b.frame_mass && !b.frame_stiffness)
        fail(*get(*s, "frame_mass"), s->display + " frame_mass without frame_stiffness; expected the frame's "
                                                  "stiffness to ground too, e.g. frame_stiffness = \"50 kN/mm\"");
    if (b.frame_stiffness && !b.frame_mass)
        fail(*get(*s, "frame_stiffness"), s->display + " frame_stiffness without frame_mass; expected the frame "
                                                       "mass too, e.g. frame_mass = \"80 kg\"");
    return b;
}

ClampInput CaseReader::read_clamp(const Section& zone) const {
    ClampInput in;
    in.length = required(zone, "length", "the clamped length, e.g. length = \"70 mm\"");
    in.where = get(zone, "length");
    at_most_one(zone, "start", "center");
    if (const auto center = quantity(zone, "center")) {
        in.centred = true;
        in.offset = *center;
        in.where = get(zone, "center");
    } else if (const auto start = quantity(zone, "start")) {
        in.offset = *start;
        in.where = get(zone, "start");
    }
    return in;
}

ClampSpec CaseReader::place_clamp(std::string name, const ClampInput& in, double core_length,
                                  bool mirrored) const {
    const double near = in.centred ? in.offset - in.length / 2 : in.offset;
    const double far = near + in.length;
    const std::string zone = "[supports." + name + "]";
    if (near < 0)
        fail(*in.where, zone + " center = " + format_quantity(in.offset, Dimension::length) +
                            " with length = " + format_quantity(in.length, Dimension::length) +
                            " starts outside the core end; expected center >= length / 2 = " +
                            format_quantity(in.length / 2, Dimension::length));
    if (far > core_length)
        fail(*in.where, zone + " ends " + format_quantity(far, Dimension::length) +
                            " from its core end, beyond [core] length = " +
                            format_quantity(core_length, Dimension::length) +
                            "; expected the clamp zone inside the core");
    ClampSpec clamp{std::move(name), near, far};
    if (mirrored) clamp = {clamp.name, core_length - far, core_length - near};
    return clamp;
}

void CaseReader::check_no_overlap(const ClampSpec& left, const ClampSpec& right,
                                  const toml::node* where) const {
    if (left.z_end <= right.z_start) return;
    const auto range = [](const ClampSpec& c) {
        return "z = " + format_quantity(c.z_start, Dimension::length) + " to " +
               format_quantity(c.z_end, Dimension::length);
    };
    fail(*where, "[supports.left] (" + range(left) + ") and [supports.right] (" + range(right) +
                     ") overlap; expected separate clamp zones, the left one ending before the "
                     "right one starts");
}

}  // namespace coremodal::case_reading
