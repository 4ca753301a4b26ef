// The case reader's parts, shared by the files that read one concept each
// (scene/case_file.cpp is the entry point; docs/reference/case-files.md the reference):
//   case_reader.cpp           messages, the schema (unknown keys, value kinds), typed values
//   case_reader_core.cpp      [core], [rest_paper] and their materials
//   case_reader_supports.cpp  [supports]: clamps, chucks, interfaces, bearings
//   case_reader_mesh.cpp      [analysis] and [mesh]
//   case_reader_rotation.cpp  [rotation]
//   case_reader_response.cpp  [damping], [excitation], [response]
//   case_reader_damping.cpp   [damping]: the base ratio or Rayleigh, families, single modes
//   case_reader_traction.cpp  [traction]: one roller under the web (Rice & Gans)
// Private to scene/: everything else reads a case through case_file.hpp.
#pragma once

#include "common/join.hpp"
#include "scene/case_schema.hpp"
#include "scene/limits_spec.hpp"
#include "scene/materials_library.hpp"
#include "scene/mesh_levels.hpp"
#include "scene/response_spec.hpp"
#include "scene/rotation_spec.hpp"
#include "scene/scene.hpp"
#include "scene/units.hpp"
#include "traction/traction_model.hpp"

#include <toml++/toml.h>

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace coremodal::case_reading {

// Chuck defaults when the file does not say (each echoed as an assumption):
// a sliding fit of a fraction of a millimetre, and a short stub to the bearing.
inline constexpr double kDefaultChuckClearance = 0.5e-3;  // m, radial
inline constexpr double kDefaultShaftLength = 0.15;       // m
// The mesh generator places nodes at 0, 90, 180 and 270 degrees (symmetry
// planes of bending pairs), so the count around must split into quarters.
inline constexpr int kAroundMultiple = 4;
// Long values are cut in messages: the message must point, not reproduce.
inline constexpr std::size_t kMaxShownChars = 60;

inline const std::vector<std::string_view> kSupportTypes = {"free", "clamped", "chucks"};
inline const std::vector<std::string_view> kInterfaceKinds = {"spring", "bonded"};
inline const std::vector<std::string_view> kContactKinds = {"uniform", "one-sided"};
inline const std::vector<std::string_view> kBearingTypes = {"rigid", "elastic"};
inline const std::vector<std::string_view> kElementTypes = {"hex20", "hex27"};

// A table of the case file, with its name in messages ("[core.material]")
// and its table in the schema ("material").
struct Section {
    const toml::table* table = nullptr;
    std::string display;  // "" for the top level
    std::string schema;
};

// A material value on its way from library or file to the OrthotropicMaterial.
struct MaterialValue {
    std::string_view key;
    double value = 0;
    std::string_view source;  // library citation; empty for user values
    bool assumed = false;
    bool from_user = false;
};
using MaterialValues = std::vector<MaterialValue>;

// One clamp zone as the file gives it, before conversion to z from the left end.
struct ClampInput {
    double length = 0;
    double offset = 0;  // start or center, from that zone's core end
    bool centred = false;
    const toml::node* where = nullptr;
};

// A value as the user wrote it, cut to kMaxShownChars (messages point, not reproduce).
std::string show(const toml::node& node);
// Names of the library materials and of the mesh levels, for messages and suggestions.
std::string library_names();
std::vector<std::string_view> library_name_list();
std::vector<std::string_view> mesh_level_names();

// The stiffness above which a spring of dimension `d` (stiffness,
// rotational_stiffness, stiffness_per_area; any other: a line spring in N/m
// per m of roll) on the roll of `core` is beyond rigid: kBeyondRigid times
// the roll's own stiffness of that kind (case_reader_supports.cpp: the rule
// and its reason). Infinite for a core with no stiffness to compare with.
double beyond_rigid(const CoreSpec& core, Dimension d);
// "the roll's own 4.4 MN/m (its core's axial E_z A / L)" for messages.
std::string beyond_rigid_reason(const CoreSpec& core, Dimension d);

// Reads one case file's TOML document into a Scene, table by table; every
// failure is an InputError pointing at the value's line and column.
class CaseReader {
public:
    explicit CaseReader(std::string path) : path_(std::move(path)) {}

    Scene read(const toml::table& root);
    // [rotation] of the same document (checked by read too).
    std::optional<RotationSpec> rotation(const toml::table& root, const Scene& scene) const;
    // [damping], [excitation] and [response] of the same document (checked by read too).
    std::optional<ResponseSetup> response(const toml::table& root, const Scene& scene) const;
    // [damping] alone (checked by read too): with [response] or [rotation] (campbell's damped modes).
    std::optional<DampingSpec> damping(const toml::table& root) const;
    // [limits] of the same document (checked by read too; case_reader_limits.cpp).
    std::optional<LimitsSpec> limits(const toml::table& root, const Scene& scene) const;
    // [traction] of the same document (checked by read too). `assumptions`
    // gets the defaults it used; the plausibility warnings go to warnings().
    std::optional<TractionSpec> traction(const toml::table& root, std::vector<std::string>& assumptions) const;
    // The top level's keys checked against the schema (a file without [core]).
    void check_top_level(const toml::table& root) const;
    const std::vector<std::string>& warnings() const { return warnings_; }

private:
    std::string path_;
    // Values that parse but look like slips (check_plausible); filled by the
    // const readers as they go, so mutable.
    mutable std::vector<std::string> warnings_;

    // ---- messages -------------------------------------------------------

    std::string location(const toml::source_region& where) const;

    [[noreturn]] void fail(const toml::source_region& where, const std::string& what) const;
    [[noreturn]] void fail(const toml::node& where, const std::string& what) const;

    static std::string name_of(const Section& s, std::string_view key);
    // "[core] length = -1.5"
    static std::string echo(const Section& s, std::string_view key, const toml::node& value);

    // ---- the schema: unknown keys and value kinds ----------------------

    Section open(const toml::table& table, std::string display, std::string schema) const;

    [[noreturn]] void unknown_key(const Section& s, const toml::key& key) const;

    void check_kind(const Section& s, const KeySpec& spec, const toml::node& value) const;

    static std::string quantity_hint(Dimension d);

    static std::string example_of(Dimension d);

    // ---- typed values ---------------------------------------------------

    static const toml::node* get(const Section& s, std::string_view key);

    std::optional<std::string> text(const Section& s, std::string_view key) const;

    // A value from a fixed list; suggests the nearest on a typo.
    std::optional<std::string> choice(const Section& s, std::string_view key,
                                      const std::vector<std::string_view>& allowed) const;

    // A quantity node converted to SI (no range check).
    double to_si(const toml::node& node, Dimension d, const std::string& what) const;

    std::optional<double> quantity(const Section& s, std::string_view key) const;

    // Outside the key's plausible range: a warning (Scene::warnings), with the
    // unit a plain number was probably meant in.
    void check_plausible(const Section& s, const KeySpec& spec, const toml::node& node, double v) const;

    // The common unit that brings a plain number v inside the range, nearest
    // the typical value (on a log scale).
    static std::optional<std::string> likely_unit(double v, Dimension d, const PlausibleRange& p);

    void check_range(const Section& s, const KeySpec& spec, const toml::node& node,
                     double v) const;

    std::optional<int> integer(const Section& s, std::string_view key) const;

    std::optional<Section> section(const Section& parent, std::string_view key,
                                   std::string schema) const;

    double required(const Section& s, std::string_view key, const std::string& expected) const;

    // At most one of two alternatives (wall or outer_diameter, start or center).
    void at_most_one(const Section& s, std::string_view a, std::string_view b) const;

    // ---- [core] ---------------------------------------------------------

    CoreSpec read_core(const Section& top, Scene& scene) const;

    // ---- [rest_paper] ---------------------------------------------------

    std::optional<RestPaperSpec> read_rest_paper(const Section& top, Scene& scene) const;
    std::optional<WebSpec> read_web(const Section& top, Scene& scene) const;

    // ---- materials ------------------------------------------------------

    OrthotropicMaterial read_material(const Section& owner, std::string_view role,
                                      std::string_view default_name, Scene& scene) const;

    const LibraryMaterial& library_entry(const Section& s, std::string_view key,
                                         const toml::node& node) const;

    // A library material, some values overridden by the user; every value the
    // user did not give becomes an assumption sentence.
    OrthotropicMaterial from_library(const LibraryMaterial& entry,
                                     const std::map<std::string_view, double>& user,
                                     std::string_view role, Scene& scene) const;

    static std::string assumption(std::string_view role, std::string_view material,
                                  const MaterialValue& v);

    OrthotropicMaterial inline_material(const Section& mat, std::string_view role,
                                        Scene& scene) const;

    OrthotropicMaterial complete_inline_material(const Section& mat,
                                                 const std::map<std::string_view, double>& user,
                                                 bool orthotropic) const;

    // ---- [supports] -----------------------------------------------------

    SupportSpec read_supports(const Section& top, Scene& scene) const;

    // ---- [supports] type = "chucks" -------------------------------------

    SupportSpec read_chucks(const Section& supports, const std::optional<Section>& left,
                            const std::optional<Section>& right, Scene& scene) const;

    ChuckSpec read_chuck(const Section& s, std::string name, Scene& scene) const;

    std::vector<ExpandingElement> read_expanding(const Section& chuck, const ChuckSpec& c) const;

    ChuckInterface read_interface(const Section& s, const std::string& chuck, Scene& scene) const;
    ContactKind read_contact(const Section& s, bool expanded) const;

    BearingSpec read_bearing(const Section& chuck, const std::string& name, Scene& scene) const;

    // Fails at `key` when a spring of `stiffness` (of the key's dimension) is
    // beyond rigid for the roll of `core` (beyond_rigid below).
    void check_not_beyond_rigid(const Section& s, std::string_view key, double stiffness, const CoreSpec& core) const;

    ClampInput read_clamp(const Section& zone) const;

    // z from the left core end; the right zone is measured from the right end.
    ClampSpec place_clamp(std::string name, const ClampInput& in, double core_length,
                          bool mirrored) const;

    void check_no_overlap(const ClampSpec& left, const ClampSpec& right,
                          const toml::node* where) const;

    // ---- [analysis] -----------------------------------------------------

    AnalysisSpec read_analysis(const Section& top) const;

    void read_band(const Section& s, const toml::node& node, AnalysisSpec& spec) const;

    // ---- [mesh] ---------------------------------------------------------

    MeshSpec read_mesh(const Section& top, const Scene& scene) const;

    const MeshLevel& mesh_level(const std::optional<Section>& mesh) const;

    void apply_mesh_overrides(const Section& mesh, MeshSpec& spec) const;

    std::string read_mesh_file(const Section& mesh) const;

    // ---- [rotation] -----------------------------------------------------

    std::optional<RotationSpec> read_rotation(const Section& top, const Scene& scene) const;

    // The speeds of speeds/web_speeds: a list, or [first, last] with points.
    std::vector<double> read_speed_list(const Section& rotation, std::string_view key, Dimension d) const;

    std::vector<int> read_excitation_orders(const Section& rotation) const;
    std::array<double, 2> read_operating_speeds(const Section& rotation, std::string_view sweep_key,
                                                const RotationSpec& spec, double roll_diameter) const;

    // ---- [traction] -----------------------------------------------------

    std::optional<TractionSpec> read_traction(const Section& top, std::vector<std::string>& assumptions) const;
    Grooves read_grooves(const Section& traction) const;
    void check_traction(const Section& traction, const TractionSpec& spec) const;

    // ---- [damping], [excitation], [response] ----------------------------

    std::optional<ResponseSetup> read_response_setup(const Section& top, const Scene& scene) const;
    DampingSpec read_damping(const Section& damping) const;
    // The base: exactly one of ratio, log_decrement, decay, rayleigh.
    void read_damping_base(const Section& damping, DampingSpec& spec) const;
    RayleighSpec read_rayleigh(const Section& damping, std::string& source) const;
    std::vector<DampingSpec::ModeRatio> read_damping_modes(const Section& damping) const;
    ExcitationSpec read_excitation(const Section& excitation, const Scene& scene) const;
    ResponseRange read_response_range(const Section& response, const Scene& scene) const;
    std::vector<ResponseRange::Probe> read_probes(const Section& response, const Scene& scene) const;

    // ---- [limits] -------------------------------------------------------

    std::optional<LimitsSpec> read_limits(const Section& top, const Scene& scene) const;
    void read_limits_diameters(const Section& limits, const Scene& scene, LimitsSpec& spec) const;
};

}  // namespace coremodal::case_reading
