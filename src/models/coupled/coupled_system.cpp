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

Eigen::Matrix3d web_between(const WebLine& web, HarmonicFamily a, HarmonicFamily b) {
    return harmonic_to_cartesian(a, web.theta).transpose() * web.stiffness * harmonic_to_cartesian(b, web.theta);
}

namespace {

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

}  // namespace coremodal
