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
    "rule of thumb: out-of-plane modulus of paper near E_MD/200, DOMAIN.md §4";
constexpr std::string_view kTransverseShear = "rule of thumb: a few per cent of E_MD, DOMAIN.md §4";
constexpr std::string_view kInPlaneAssumed =
    "assumed: in-plane values typical of paperboard (CD stiffness about 60 % of MD), DOMAIN.md §4";
constexpr std::string_view kSmallOutOfPlanePoisson =
    "rule of thumb: out-of-plane Poisson ratios of paper are small, DOMAIN.md §4, §6";
constexpr std::string_view kJorkama =
    "Jorkama & von Hertzen: wound roll radial modulus of order 10 MPa, DOMAIN.md §3-4";
constexpr std::string_view kInPlaneEqual =
    "assumed equal to the measured cylinder modulus E_z (a wound roll's MD lies around it)";
constexpr std::string_view kSteel = "handbook value for structural steel";

std::vector<LibraryValue> paperboard_core() {
    return {
        {"E_r", 33e6, kOutOfPlane, true},
        {"E_theta", 4.0e9, kInPlaneAssumed, true},
        {"E_z", 6.5e9, kIlomakiCore, false},
        {"G_rtheta", 130e6, kTransverseShear, true},
        {"G_rz", 130e6, kTransverseShear, true},
        {"G_thetaz", 1.8e9, kInPlaneAssumed, true},
        {"nu_rtheta", 0.002, kSmallOutOfPlanePoisson, true},
        {"nu_rz", 0.002, kSmallOutOfPlanePoisson, true},
        {"nu_thetaz", 0.3, kInPlaneAssumed, true},
        {"density", 920.0, kIlomakiCore, false},
    };
}

// A wound rest roll is in-plane isotropic to the precision we know it: the
// cylinder modulus Ep was measured on the roll, not split into MD and CD.
std::vector<LibraryValue> rest_paper(double E_inplane, double density, std::string_view source) {
    return {
        {"E_r", 10e6, kJorkama, true},
        {"E_theta", E_inplane, kInPlaneEqual, true},
        {"E_z", E_inplane, source, false},
        {"G_rtheta", 50e6, kTransverseShear, true},
        {"G_rz", 50e6, kTransverseShear, true},
        {"G_thetaz", 1.5e9 * E_inplane / 5.0e9, kInPlaneAssumed, true},
        {"nu_rtheta", 0.002, kSmallOutOfPlanePoisson, true},
        {"nu_rz", 0.002, kSmallOutOfPlanePoisson, true},
        {"nu_thetaz", 0.3, kInPlaneAssumed, true},
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
