#include "models/coupled/coupled_system.hpp"

#include "common/error.hpp"
#include "common/format.hpp"
#include "effects/chuck_placement.hpp"
#include "effects/web.hpp"

#include <algorithm>
#include <map>
#include <cmath>
#include <cstdint>

namespace coremodal {

Scene with_full_bands(const Scene& scene) {
    Scene band = scene;
    for (ChuckSpec& chuck : band.supports.chucks)
        for (ExpandingElement& e : chuck.expanding) {
            e.segments = 0;
            e.segment_angle = 0;
        }
    return band;
}

std::vector<PadLayer> pad_layers(const Scene& scene) {
    std::vector<PadLayer> out;
    const SupportEffects effects = support_effects(scene);
    for (const ChuckEffects& chuck : effects.chucks)
        for (const ExpandingElement& e : chuck.placement.expanding) {
            if (e.segments == 0 || chuck.one_sided) continue;
            if (!chuck.spring_layer)
                throw InputError(scene.source_file + ": model = \"coupled\": the " + chuck.placement.chuck +
                                 " chuck's segmented element at " + significant(e.center * 1e3) + " mm is " +
                                 "bonded" +
                                 "; the coupled level models segments as a spring layer; expected interface = "
                                 "\"spring\" and an expanded chuck, or model = \"solid\"");
            out.push_back({chuck.placement.chuck, chuck.placement.element_range(e), contact_arcs(e), e.segments,
                           *chuck.spring_layer});
        }
    return out;
}

Eigen::Matrix3d harmonic_to_cartesian(HarmonicFamily h, double theta) {
    const double c = std::cos(theta), s = std::sin(theta);
    const double t_r = trig_factor(h, 0, theta), t_t = trig_factor(h, 1, theta), t_z = trig_factor(h, 2, theta);
    Eigen::Matrix3d B;
    B << c * t_r, -s * t_t, 0, s * t_r, c * t_t, 0, 0, 0, t_z;
    return B;
}

namespace {

// B_a^T K_line B_b: the web's line between blocks a and b, per unit length
// and per pair of node values.
Eigen::Matrix3d web_between(const WebLine& web, HarmonicFamily a, HarmonicFamily b) {
    return harmonic_to_cartesian(a, web.theta).transpose() * web.stiffness * harmonic_to_cartesian(b, web.theta);
}

// Below this share of the line's stiffness an entry is round-off of one that
// vanishes exactly (sin n theta at theta on a symmetry line).
constexpr double kVanishingShare = 1e-12;

bool pads_couple(const std::vector<PadLayer>& pads, HarmonicFamily a, HarmonicFamily b, int c) {
    const std::vector<Arc> band = {{0, 2 * M_PI}};
    for (const PadLayer& pad : pads)
        if (pad_integral(pad.arcs, a, b, c) != pad_integral(band, a, b, c)) return true;
    return false;
}

}  // namespace

bool Attachments::couple(HarmonicFamily a, int ca, HarmonicFamily b, int cb) const {
    // The pads and the contact act on (r, theta, z) componentwise; the web's line in x, y, z mixes them.
    if (ca == cb && pads_couple(pads, a, b, ca)) return true;
    // A contact not yet solved is assumed to couple everything (it will, but for symmetry).
    if (ca == cb && one_sided && (!contact || contact_couples(*contact, a, b, ca))) return true;
    return web && std::abs(web_between(*web, a, b)(ca, cb)) > kVanishingShare * web->stiffness.norm();
}

bool Attachments::couple(HarmonicFamily a, HarmonicFamily b) const {
    for (int ca = 0; ca < 3; ++ca)
        for (int cb = 0; cb < 3; ++cb)
            if (couple(a, ca, b, cb)) return true;
    return false;
}

int Attachments::step() const {
    int reach = 0;
    for (const PadLayer& p : pads) reach = reach == 0 ? p.segments : std::min(reach, p.segments);
    return reach > 0 ? reach : web || one_sided ? 1 : 0;
}

Attachments attachments(const Scene& scene) {
    Attachments out;
    out.pads = pad_layers(scene);
    for (const ChuckEffects& chuck : support_effects(scene).chucks) out.one_sided = out.one_sided || chuck.one_sided;
    if (scene.web) {
        const Eigen::Vector3d p = web_tangent_normal(*scene.web);
        out.web = WebLine{std::atan2(p.y(), p.x()), web_line_stiffness(*scene.web)};
    }
    return out;
}

int CoupledDofs::block_of(int n, Family family) const {
    for (size_t b = 0; b < blocks.size(); ++b)
        if (blocks[b].harmonic == HarmonicFamily{n, family}) return static_cast<int>(b);
    return -1;
}

std::optional<LocalHarmonics> local_harmonics(const Attachments& attached, const SectionMesh& mesh) {
    if (attached.web || (attached.pads.empty() && !attached.contact)) return std::nullopt;
    double r_max = 0;
    for (const auto& [r, z] : mesh.nodes) r_max = std::max(r_max, r);
    LocalHarmonics local{1, {}, kLocalReach * 2 * r_max};
    for (const PadLayer& pad : attached.pads) local.pads.push_back(pad.zone);
    if (attached.contact) {
        // Each one-sided chuck's points span its interface along z.
        std::map<int, ZRange> zones;
        for (const HarmonicContactPoint& p : attached.contact->points) {
            const double z = p.bore.x[2];
            const auto [it, fresh] = zones.try_emplace(p.bore.chuck, ZRange{z, z});
            it->second.lo = std::min(it->second.lo, z);
            it->second.hi = std::max(it->second.hi, z);
        }
        for (const auto& [chuck, zone] : zones) local.pads.push_back(zone);
    }
    return local;
}

namespace {

std::vector<bool> is_far(const SectionMesh& mesh, const LocalHarmonics& local, int n) {
    std::vector<bool> far(mesh.n_nodes());
    const double reach = local.reach(n);
    for (int node = 0; node < mesh.n_nodes(); ++node) {
        const double z = mesh.nodes[node][1];
        far[node] = std::none_of(local.pads.begin(), local.pads.end(), [&](const ZRange& pad) { return pad.holds(z, reach); });
    }
    return far;
}

}  // namespace

std::vector<int> far_nodes(const SectionMesh& mesh, const LocalHarmonics& local, int n) {
    const std::vector<bool> far = is_far(mesh, local, n);
    std::vector<int> out;
    for (int node = 0; node < mesh.n_nodes(); ++node)
        if (far[node]) out.push_back(node);
    return out;
}

std::vector<int> zone_edge_nodes(const SectionMesh& mesh, const LocalHarmonics& local, int n) {
    const std::vector<bool> far = is_far(mesh, local, n);
    std::vector<bool> edge(mesh.n_nodes(), false);
    for (const auto& cell : mesh.cells)
        if (std::any_of(cell.begin(), cell.end(), [&](int node) { return far[node]; }))
            for (int node : cell) edge[node] = edge[node] || !far[node];
    std::vector<int> out;
    for (int node = 0; node < mesh.n_nodes(); ++node)
        if (edge[node]) out.push_back(node);
    return out;
}

CoupledDofs coupled_dofs(const Scene& scene, const SectionMesh& mesh, int n_max,
                         const std::optional<LocalHarmonics>& local) {
    const Scene band = with_full_bands(scene);
    CoupledDofs out;
    out.n_max = n_max;
    for (int n = 0; n <= n_max; ++n) {
        const HarmonicDofs dofs = harmonic_dofs(band, mesh, n, local && n > local->n_full ? far_nodes(mesh, *local, n) : std::vector<int>{});
        for (Family f : {Family::cos, Family::sin}) {
            if (n == 0 && f == Family::sin) continue;
            out.blocks.push_back({{n, f}, dofs, out.n_dofs});
            out.n_dofs += dofs.n_dofs;
        }
    }
    return out;
}

namespace {

// One pad layer's coupling between blocks a and b, component c, up to the
// edge integrals (which are the same for every pair): I_pads - I_band.
double pad_coupling(const PadLayer& pad, HarmonicFamily a, HarmonicFamily b, int c) {
    const std::vector<Arc> band = {{0, 2 * M_PI}};
    return pad_integral(pad.arcs, a, b, c) - pad_integral(band, a, b, c);
}

// s per block when `sin` is the partner of `cos` (see CoupledComponent), else nothing.
std::optional<std::vector<double>> partner_signs(const CoupledDofs& cos, const CoupledDofs& sin,
                                                 const Attachments& attached) {
    const size_t n = cos.blocks.size();
    if (attached.web || attached.one_sided || n != sin.blocks.size()) return std::nullopt;
    for (size_t i = 0; i < n; ++i) {
        const HarmonicFamily a = cos.blocks[i].harmonic, b = sin.blocks[i].harmonic;
        if (a.n < 1 || a.n != b.n || a.family != Family::cos || b.family != Family::sin) return std::nullopt;
    }
    const auto value = [&](const PadLayer& pad, const CoupledDofs& d, size_t i, size_t j, int c) {
        return pad_coupling(pad, d.blocks[i].harmonic, d.blocks[j].harmonic, c);
    };
    // Signs spread from block 0 along the couplings; then every pair of every layer is checked.
    std::vector<double> s(n, 0.0);
    s[0] = 1;
    for (bool grew = true; grew;) {
        grew = false;
        for (const PadLayer& pad : attached.pads)
            for (size_t i = 0; i < n; ++i)
                for (size_t j = 0; j < n && s[i] != 0; ++j)
                    for (int c = 0; c < 3 && s[j] == 0; ++c)
                        if (const double v = value(pad, cos, i, j, c); v != 0) {
                            s[j] = s[i] * (value(pad, sin, i, j, c) * v > 0 ? 1 : -1);
                            grew = true;
                        }
    }
    for (double& x : s)
        if (x == 0) x = 1;  // a block nothing couples to the rest
    for (const PadLayer& pad : attached.pads)
        for (size_t i = 0; i < n; ++i)
            for (size_t j = 0; j < n; ++j)
                for (int c = 0; c < 3; ++c) {
                    const double v = value(pad, cos, i, j, c), w = value(pad, sin, i, j, c);
                    if (std::abs(w - s[i] * s[j] * v) > kVanishingIntegral * 2 * M_PI) return std::nullopt;
                }
    return s;
}

}  // namespace

namespace {

// The part of block n = 0 with only the components `keep` (U, W or V; the
// frame's axial DOF goes with W), renumbered; `dof_in` gets each DOF's place in `all`.
CoupledBlock part_of_block(const CoupledBlock& whole, bool torsion, std::vector<int>& dof_in) {
    CoupledBlock part = whole;
    std::vector<int> renumbered(whole.dofs.n_dofs, -1);
    const auto keep = [&](int& d) {
        if (d < 0) return;
        if (renumbered[d] < 0) {
            renumbered[d] = static_cast<int>(dof_in.size());
            dof_in.push_back(whole.offset + d);
        }
        d = renumbered[d];
    };
    for (size_t i = 0; i < part.dofs.of_component.size(); ++i) {
        int& d = part.dofs.of_component[i];
        if ((i % 3 == 1) == torsion)
            keep(d);
        else
            d = -1;
    }
    for (int& d : part.dofs.frame)
        if (torsion)
            d = -1;
        else
            keep(d);
    part.dofs.n_dofs = static_cast<int>(dof_in.size());
    return part;
}

}  // namespace

std::vector<CoupledComponent> coupled_components(const CoupledDofs& all, const Attachments& attached) {
    // Graph nodes: one per block, and one more (index n) for n = 0's torsion V.
    const int n = static_cast<int>(all.blocks.size());
    const auto node = [&](int b, int c) { return all.blocks[b].harmonic.n == 0 && c == 1 ? n : b; };
    std::vector<int> root(n + 1);
    for (int b = 0; b <= n; ++b) root[b] = b;
    const auto find = [&](int b) {
        while (root[b] != b) b = root[b] = root[root[b]];
        return b;
    };
    for (int a = 0; a < n; ++a)
        for (int b = a; b < n; ++b)
            for (int ca = 0; ca < 3; ++ca)
                for (int cb = 0; cb < 3; ++cb)
                    if (node(a, ca) != node(b, cb) && find(node(a, ca)) != find(node(b, cb)) &&
                        attached.couple(all.blocks[a].harmonic, ca, all.blocks[b].harmonic, cb))
                        root[find(node(a, ca))] = find(node(b, cb));
    std::vector<CoupledComponent> out;
    std::vector<int> component_of_root(n + 1, -1);
    const auto add = [&](int graph_node, CoupledBlock block, std::vector<int> dof_in) {
        int& c = component_of_root[find(graph_node)];
        if (c < 0) {
            c = static_cast<int>(out.size());
            out.emplace_back();
            out.back().dofs.n_max = all.n_max;
        }
        CoupledComponent& comp = out[c];
        comp.offset_in.push_back(block.offset);
        comp.dof_in.push_back(std::move(dof_in));
        block.offset = comp.dofs.n_dofs;
        comp.dofs.n_dofs += block.dofs.n_dofs;
        comp.dofs.blocks.push_back(std::move(block));
    };
    for (int b = 0; b < n; ++b) {
        if (all.blocks[b].harmonic.n != 0 || find(b) == find(n)) {
            add(b, all.blocks[b], {});
            continue;
        }
        for (bool torsion : {false, true}) {  // two independent parts of n = 0
            std::vector<int> dof_in;
            CoupledBlock part = part_of_block(all.blocks[b], torsion, dof_in);
            add(torsion ? n : b, std::move(part), std::move(dof_in));
        }
    }
    for (size_t c = 0; c < out.size(); ++c)
        for (size_t p = 0; p < c && out[c].partner_of < 0; ++p)
            if (out[p].partner_of < 0)
                if (auto signs = partner_signs(out[p].dofs, out[c].dofs, attached)) {
                    out[c].partner_of = static_cast<int>(p);
                    out[c].block_sign = std::move(*signs);
                }
    return out;
}

namespace {

std::vector<int> shifted(std::vector<int> dofs, int offset) {
    for (int& d : dofs)
        if (d >= 0) d += offset;
    return dofs;
}

// The global DOFs of a section edge's three nodes (U, V, W each) in a block.
std::vector<int> edge_dofs(const CoupledBlock& block, const SectionEdge& e) {
    std::vector<int> out;
    for (int p = 0; p < 3; ++p)
        for (int c = 0; c < 3; ++c) {
            const int d = block.dofs.of_component[3 * e[p] + c];
            out.push_back(d < 0 ? -1 : d + block.offset);
        }
    return out;
}

// The pad layer's deviation from the full band on one interface edge pair:
// k_c (I_pads - I_band)(a, b) int N_i N_j r ds on core minus chuck, for
// every pair of blocks it couples (the diagonal pairs included: there it
// takes the band's share of the pads' gaps away).
void add_pad_coupling(const SectionMesh& mesh, const PadLayer& pad, const SectionEdge& core, const SectionEdge& body,
                      const CoupledDofs& dofs, const CoupledInsert& insert) {
    Eigen::Matrix<double, 3, 2> x;
    for (int p = 0; p < 3; ++p) x.row(p) << mesh.nodes[core[p]][0], mesh.nodes[core[p]][1];
    // int N_i N_j diag(k) r ds: harmonic_edge_spring's w_n = pi for n = 1 taken out.
    const Eigen::Matrix<double, 9, 9> edge = harmonic_edge_spring(x, pad.layer.per_area_cylindrical(), 1) / M_PI;
    const Eigen::MatrixXd between = spring_between(edge);  // 18 x 18, node-major (U, V, W) on core then chuck
    const std::vector<Arc> band = {{0, 2 * M_PI}};
    for (const CoupledBlock& a : dofs.blocks)
        for (const CoupledBlock& b : dofs.blocks) {
            std::array<double, 3> scale{};
            bool any = false;
            for (int c = 0; c < 3; ++c) {
                scale[c] = pad_integral(pad.arcs, a.harmonic, b.harmonic, c) -
                           pad_integral(band, a.harmonic, b.harmonic, c);
                any = any || scale[c] != 0;
            }
            if (!any) continue;
            Eigen::MatrixXd K = between;
            for (int i = 0; i < 18; ++i) K.row(i) *= scale[i % 3];  // diag(k): rows and columns share a component
            std::vector<int> rows = edge_dofs(a, core), cols = edge_dofs(b, core);
            const std::vector<int> rows_body = edge_dofs(a, body), cols_body = edge_dofs(b, body);
            rows.insert(rows.end(), rows_body.begin(), rows_body.end());
            cols.insert(cols.end(), cols_body.begin(), cols_body.end());
            insert(SpringLayer::kTerm, rows, cols, K);
        }
}

// The web's line on one edge of the roll's outer surface (r constant):
// int N_i N_j dz B_a^T K_line B_b for every pair of blocks it couples.
void add_web_coupling(const SectionMesh& mesh, const WebLine& web, const SectionEdge& edge, const CoupledDofs& dofs,
                      const CoupledInsert& insert) {
    Eigen::Matrix<double, 3, 2> x;
    for (int p = 0; p < 3; ++p) x.row(p) << mesh.nodes[edge[p]][0], mesh.nodes[edge[p]][1];
    // int N_i N_j r ds (times the identity, node-major): harmonic_edge_spring's w_n = pi for n = 1 and r taken out.
    const Eigen::Matrix<double, 9, 9> weights = harmonic_edge_spring(x, Eigen::Vector3d::Ones(), 1) / (M_PI * x(0, 0));
    for (const CoupledBlock& a : dofs.blocks)
        for (const CoupledBlock& b : dofs.blocks) {
            const Eigen::Matrix3d k = web_between(web, a.harmonic, b.harmonic);
            if (k.cwiseAbs().maxCoeff() <= kVanishingShare * web.stiffness.norm()) continue;
            Eigen::MatrixXd K(9, 9);
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j) K.block<3, 3>(3 * i, 3 * j) = weights(3 * i, 3 * j) * k;
            insert(Term::stiffness, edge_dofs(a, edge), edge_dofs(b, edge), K);
        }
}

// The one-sided contact's layer on each interface edge pair of its chucks:
// contact_edge_matrix between every pair of blocks it couples, on core minus chuck.
void add_contact_coupling(const SectionMesh& mesh, const SupportEffects& effects, const ContactLayer& layer,
                          const CoupledDofs& dofs, const CoupledInsert& insert) {
    for (size_t first = 0, last = 0; first < layer.points.size(); first = last) {
        const HarmonicContactPoint& p = layer.points[first];
        for (last = first; last < layer.points.size() && layer.points[last].bore.chuck == p.bore.chuck &&
                           layer.points[last].edge == p.edge;
             ++last) {
        }
        const std::string& chuck = effects.chucks.at(p.bore.chuck).placement.chuck;
        const SectionEdge& core = mesh.edge_groups.at("interface_" + chuck + "_core").at(p.edge);
        const SectionEdge& body = mesh.edge_groups.at("interface_" + chuck + "_chuck").at(p.edge);
        for (const CoupledBlock& a : dofs.blocks)
            for (const CoupledBlock& b : dofs.blocks) {
                const Eigen::Matrix<double, 9, 9> edge = contact_edge_matrix(layer, first, last, a.harmonic, b.harmonic);
                if (edge.isZero(0)) continue;
                std::vector<int> rows = edge_dofs(a, core), cols = edge_dofs(b, core);
                const std::vector<int> rows_body = edge_dofs(a, body), cols_body = edge_dofs(b, body);
                rows.insert(rows.end(), rows_body.begin(), rows_body.end());
                cols.insert(cols.end(), cols_body.begin(), cols_body.end());
                insert(OneSidedContact::kTerm, rows, cols, spring_between(edge));
            }
    }
}

}  // namespace

double assemble_coupled_terms(const Scene& scene, const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                              const CoupledDofs& dofs, const CoupledInsert& insert) {
    return assemble_coupled_terms(scene, mesh, materials, dofs, attachments(scene), insert);
}

double assemble_coupled_terms(const Scene& scene, const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                              const CoupledDofs& dofs, const Attachments& attached, const CoupledInsert& insert) {
    const Scene band = with_full_bands(scene);
    double mass = 0;
    for (const CoupledBlock& block : dofs.blocks) {
        const double m = assemble_harmonic_terms(
            band, mesh, materials, block.dofs, block.harmonic.n,
            [&](Term t, const std::vector<int>& d, const Eigen::MatrixXd& A) {
                const std::vector<int> g = shifted(d, block.offset);
                insert(t, g, g, A);
            });
        if (block.harmonic.n == 0) mass = m;
    }
    COREMODAL_ASSERT(!attached.one_sided || attached.contact);  // the level solves the static state first
    if (attached.contact) add_contact_coupling(mesh, support_effects(scene), *attached.contact, dofs, insert);
    if (attached.web)
        for (const SectionEdge& e : mesh.edge_groups.at("roll_outer")) add_web_coupling(mesh, *attached.web, e, dofs, insert);
    for (const PadLayer& pad : attached.pads) {
        const auto& core = mesh.edge_groups.at("interface_" + pad.chuck + "_core");
        const auto& body = mesh.edge_groups.at("interface_" + pad.chuck + "_chuck");
        for (size_t e = 0; e < core.size(); ++e) {
            const double z = mesh.nodes[core[e][2]][1];  // the middle node
            if (pad.zone.holds(z, 0)) add_pad_coupling(mesh, pad, core[e], body[e], dofs, insert);
        }
    }
    return mass;
}

CoupledSystem assemble_coupled(const Scene& scene, const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                               const CoupledDofs& dofs, MPI_Comm comm) {
    return assemble_coupled(scene, mesh, materials, dofs, attachments(scene), comm);
}

namespace {

// The symmetric n x n AIJ matrix of the coordinate entries (i, j, values),
// duplicates added; i and j are copies: PETSc may reorder the arrays it is given.
PetscMatrix symmetric_coo_matrix(MPI_Comm comm, PetscInt n, std::vector<PetscInt> i, std::vector<PetscInt> j,
                                 const std::vector<PetscScalar>& values) {
    PetscMatrix A;
    COREMODAL_PETSC(MatCreate(comm, A.out()));
    COREMODAL_PETSC(MatSetSizes(A, PETSC_DECIDE, PETSC_DECIDE, n, n));
    COREMODAL_PETSC(MatSetType(A, MATAIJ));
    COREMODAL_PETSC(MatSetPreallocationCOO(A, static_cast<PetscCount>(i.size()), i.data(), j.data()));
    COREMODAL_PETSC(MatSetValuesCOO(A, values.data(), ADD_VALUES));
    COREMODAL_PETSC(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
    COREMODAL_PETSC(MatSetOption(A, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
    return A;
}

}  // namespace

CoupledSystem assemble_coupled(const Scene& scene, const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                               const CoupledDofs& dofs, const Attachments& attached, MPI_Comm comm) {
    CoupledSystem system;
    system.dofs = dofs;
    // Coordinate entries for PETSc's COO assembly; every term gets the union
    // pattern (zeros where it has none), so K - sigma M keeps one pattern.
    // The element entries (millions at N ~ 20) are summed here first: sorting
    // 64-bit keys is cheaper than PETSc's preallocation of every duplicate.
    struct Entry {
        std::int64_t key;  // row * n_dofs + column
        double k, m;
    };
    std::vector<Entry> raw;
    const std::int64_t n = system.dofs.n_dofs;
    if (mpi_rank(comm) == 0) {
        system.operators.model_mass = assemble_coupled_terms(
            scene, mesh, materials, system.dofs, attached,
            [&](Term t, const std::vector<int>& rows, const std::vector<int>& cols, const Eigen::MatrixXd& A) {
                for (size_t a = 0; a < rows.size(); ++a)
                    for (size_t b = 0; b < cols.size(); ++b) {
                        if (rows[a] < 0 || cols[b] < 0 || A(a, b) == 0) continue;
                        raw.push_back({rows[a] * n + cols[b], t == Term::stiffness ? A(a, b) : 0.0,
                                       t == Term::mass ? A(a, b) : 0.0});
                    }
            });
        std::sort(raw.begin(), raw.end(), [](const Entry& x, const Entry& y) { return x.key < y.key; });
    }
    std::vector<PetscInt> i, j;
    std::vector<PetscScalar> k_values, m_values;
    for (size_t e = 0; e < raw.size(); ++e) {
        if (e > 0 && raw[e].key == raw[e - 1].key) {
            k_values.back() += raw[e].k;
            m_values.back() += raw[e].m;
            continue;
        }
        i.push_back(static_cast<PetscInt>(raw[e].key / n));
        j.push_back(static_cast<PetscInt>(raw[e].key % n));
        k_values.push_back(raw[e].k);
        m_values.push_back(raw[e].m);
    }
    raw = {};
    const auto block_of_dof = [&](int d) {
        int b = 0;
        while (b + 1 < static_cast<int>(system.dofs.blocks.size()) && system.dofs.blocks[b + 1].offset <= d) ++b;
        return b;
    };
    for (size_t e = 0; e < i.size(); ++e)
        if (k_values[e] != 0 && block_of_dof(static_cast<int>(i[e])) != block_of_dof(static_cast<int>(j[e])))
            ++system.n_coupling_entries;
    MPI_Bcast(&system.operators.model_mass, 1, MPI_DOUBLE, 0, comm);
    for (Term t : {Term::stiffness, Term::mass})
        system.operators.matrices[t] =
            symmetric_coo_matrix(comm, system.dofs.n_dofs, i, j, t == Term::stiffness ? k_values : m_values);
    return system;
}

}  // namespace coremodal
