#include "scene/materials_library.hpp"

namespace coremodal {
namespace {

// Sources, cited once so every value says where it comes from.
constexpr std::string_view kIlomakiCore =
    "Ilomäki, On the durability of cores and rest roll dynamics: high-quality 150 mm core";
constexpr std::string_view kIlomakiRestPaper =
    "Ilomäki, On the durability of cores and rest roll dynamics: measured on rest rolls";
constexpr std::string_view kKoenig =
    "König & Müller, Hartpapierhülsen in Papierrollen im Tiefdruck (1988)";
constexpr std::string_view kOutOfPlane =
    "rule of thumb: out-of-plane modulus of paper near E_MD/200, docs/reference/material-sources.md";
constexpr std::string_view kTransverseShear = "rule of thumb: a few per cent of E_MD, docs/reference/material-sources.md";
constexpr std::string_view kInPlaneAssumed =
    "assumed: in-plane values typical of paperboard (CD stiffness about 60 % of MD), docs/reference/material-sources.md";
constexpr std::string_view kSmallOutOfPlanePoisson =
    "rule of thumb: out-of-plane Poisson ratios of paper are small, docs/reference/material-sources.md";
constexpr std::string_view kJorkama =
    "Jorkama & von Hertzen: wound roll radial modulus of order 10 MPa (Fig. 4), docs/reference/references.md";
constexpr std::string_view kInPlaneEqual =
    "assumed equal to the measured cylinder modulus E_z (a wound roll's MD lies around it)";
constexpr std::string_view kSteel = "handbook value for structural steel";

// Published values, checked sources and the range to use for every value
// below: docs/reference/material-sources.md. "Suggested" ranges are judgements, not
// measurements; no measured out-of-plane constant of a core wall was found.
std::vector<LibraryValue> paperboard_core() {
    return {
        // Gerhardt 1990: spiral tubes have an "extremely small" radial modulus
        // (no number read); the E_MD/200 rule (Baum et al.) not checked.
        // Suggested 20-100 MPa; k is sensitive (in series with the contact).
        {"E_r", 33e6, kOutOfPlane, true},
        // No source for cores; suggested 2.5-6.5 GPa. Ovalling, breathing.
        {"E_theta", 4.0e9, kInPlaneAssumed, true},
        // Ilomaki's measured Ec (ISO 11093-8); use the core's own ISO value.
        {"E_z", 6.5e9, kIlomakiCore, false},
        // No measured value found; suggested as G_rz (out-of-plane shear is
        // nearly isotropic in the plane: TAPPI PaperCon 2019 torsion study).
        {"G_rtheta", 130e6, kTransverseShear, true},
        // No measured value found (fibre shear modulus 2.1-2.5 GPa, Dauer et al.
        // 2021, is a far upper bound). Suggested 50-650 MPa; k is sensitive
        // (case 08: 0.768 at 130 MPa, 0.791 at 650 MPa). Fit it.
        {"G_rz", 130e6, kTransverseShear, true},
        // The classical relation from E_theta, E_z, nu_thetaz gives 1.84 GPa;
        // suggested 1.2-2.5 GPa. The tube's beam shear (f2), torsion.
        {"G_thetaz", 1.8e9, kInPlaneAssumed, true},
        // Sign uncertain (paper can be auxetic out of plane); suggested
        // -0.005 to +0.005 while the compliance stays positive definite.
        {"nu_rtheta", 0.002, kSmallOutOfPlanePoisson, true},
        {"nu_rz", 0.002, kSmallOutOfPlanePoisson, true},
        // 1/3 for isotropic sheets (Fibre Sci. Technol. 1983); 0.2-0.4.
        {"nu_thetaz", 0.3, kInPlaneAssumed, true},
        // Ilomaki's 150 mm core; weigh the core in question.
        {"density", 920.0, kIlomakiCore, false},
    };
}

// A wound rest roll is in-plane isotropic to the precision we know it: the
// cylinder modulus Ep was measured on the roll, not split into MD and CD.
// Sources and ranges: docs/reference/material-sources.md, "Rest paper".
std::vector<LibraryValue> rest_paper(double E_inplane, double density, std::string_view source) {
    return {
        // Jorkama's 9.8 MPa example; a stack's modulus rises with interlayer
        // pressure (Pfeiffer). Suggested 5-50 MPa.
        {"E_r", 10e6, kJorkama, true},
        // The paper's MD; likely >= E_z (the CD), not checked.
        {"E_theta", E_inplane, kInPlaneEqual, true},
        // Ep: 5000 MPa (Ilomaki) against 1800 MPa (Koenig); measure it (I-15).
        {"E_z", E_inplane, source, false},
        // No source: interlayer shear is held by friction. Suggested 1-100 MPa;
        // decides whether thick rest paper bends as one cylinder.
        {"G_rtheta", 50e6, kTransverseShear, true},
        {"G_rz", 50e6, kTransverseShear, true},
        // 0.3 Ep (isotropic would be 0.38 Ep); suggested 0.25-0.4 Ep.
        {"G_thetaz", 1.5e9 * E_inplane / 5.0e9, kInPlaneAssumed, true},
        // As the core; with E_r = 10 MPa this gives nu_zr = E_z/E_r * 0.002
        // (1.0 for rest_paper), not a measured value.
        {"nu_rtheta", 0.002, kSmallOutOfPlanePoisson, true},
        {"nu_rz", 0.002, kSmallOutOfPlanePoisson, true},
        {"nu_thetaz", 0.3, kInPlaneAssumed, true},
        // 1350 kg/m^3 (Ilomaki) exceeds the densest calendered coated sheets
        // (1110-1160 kg/m^3) and a roll holds air: questioned in the doc, kept.
        // Suggested 1000-1200 (rotogravure grades), 600-800 (news).
        {"density", density, source, false},
    };
}

double value_of(const LibraryMaterial& entry, std::string_view key) {
    for (const LibraryValue& v : entry.values)
        if (v.key == key) return v.value;
    return 0;
}

}  // namespace

const std::vector<std::string_view>& isotropic_material_keys() {
    static const std::vector<std::string_view> keys = {"E", "nu", "density"};
    return keys;
}

const std::vector<std::string_view>& orthotropic_material_keys() {
    static const std::vector<std::string_view> keys = {
        "E_r",      "E_theta",   "E_z",   "G_rtheta",  "G_rz",
        "G_thetaz", "nu_rtheta", "nu_rz", "nu_thetaz", "density"};
    return keys;
}

const std::vector<LibraryMaterial>& material_library() {
    static const std::vector<LibraryMaterial> library = {
        {"paperboard_core", false, paperboard_core()},
        {"rest_paper", false, rest_paper(5.0e9, 1350.0, kIlomakiRestPaper)},
        {"rest_paper_koenig", false, rest_paper(1.8e9, 1200.0, kKoenig)},
        // EN 1993-1-1 3.2.6: E = 210 000 N/mm^2, nu = 0.3, rho = 7850 kg/m^3.
        {"steel",
         true,
         {{"E", 210e9, kSteel, false},
          {"nu", 0.3, kSteel, false},
          {"density", 7850.0, kSteel, false}}},
    };
    return library;
}

const LibraryMaterial* find_library_material(std::string_view name) {
    for (const LibraryMaterial& entry : material_library())
        if (entry.name == name) return &entry;
    return nullptr;
}

OrthotropicMaterial to_material(const LibraryMaterial& entry) {
    const std::string source = "library '" + std::string(entry.name) + "'";
    if (entry.isotropic)
        return OrthotropicMaterial::isotropic(std::string(entry.name), value_of(entry, "E"),
                                              value_of(entry, "nu"), value_of(entry, "density"),
                                              source);
    OrthotropicMaterial m;
    m.name = entry.name;
    m.E_r = value_of(entry, "E_r");
    m.E_theta = value_of(entry, "E_theta");
    m.E_z = value_of(entry, "E_z");
    m.G_rtheta = value_of(entry, "G_rtheta");
    m.G_rz = value_of(entry, "G_rz");
    m.G_thetaz = value_of(entry, "G_thetaz");
    m.nu_rtheta = value_of(entry, "nu_rtheta");
    m.nu_rz = value_of(entry, "nu_rz");
    m.nu_thetaz = value_of(entry, "nu_thetaz");
    m.density = value_of(entry, "density");
    m.source = source;
    return m;
}

}  // namespace coremodal
