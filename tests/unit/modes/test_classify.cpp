// Naming modes in which the roll moves as a rigid body (issue 33, item 13):
// shapes built by hand on a generated core mesh, so that the truth is known
// exactly: a rigid motion plus a small deformation, and bending shapes that
// must stay "bending".
#include "modes/classify.hpp"

#include "verification/tube_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;
using namespace coremodal::testing;

namespace {

constexpr double kLength = 1.0;
// Any eigenvalue far above the rigid line: the motions below are not at
// zero frequency (a spinning body's nutation, a roll on soft chucks).
constexpr double kLambdaScale = 1e4, kLambda = 1e3 * kLambdaScale;

// u(x) at every node, node-major.
template <class Field>
std::vector<double> shape_of(const Mesh& mesh, Field u) {
    std::vector<double> shape;
    for (const auto& x : mesh.nodes) {
        const std::array<double, 3> v = u(x);
        shape.insert(shape.end(), v.begin(), v.end());
    }
    return shape;
}

const Mesh& core_mesh() {
    static const Mesh mesh = generated_mesh(paper_core(kLength, 16, 12));
    return mesh;
}

}  // namespace

TEST_CASE("A roll rocking or swinging rigidly on its supports is a support mode, a free body's a rigid one",
          "[classify]") {
    const Mesh& mesh = core_mesh();
    const double zc = kLength / 2;
    // Rocking: a tilt about x through the middle, with a ring deformation of
    // 2 % of its amplitude (a bending ripple, as a real support mode carries).
    const auto rocking = [&](const std::array<double, 3>& x) -> std::array<double, 3> {
        const double ripple = 0.02 * std::sin(M_PI * x[2] / kLength);
        return {0, -(x[2] - zc) + ripple, x[1]};
    };
    const ModeClassifier held(mesh, roll_nodes(mesh), BodyHeld::held);
    const ModeClassifier free_body(mesh, roll_nodes(mesh), BodyHeld::free);
    const std::vector<double> tilt = shape_of(mesh, rocking);
    CHECK(held.deformation_share(tilt) < 1e-3);
    const ModeLabel rock = held.classify(tilt, kLambda, kLambdaScale);
    CHECK(rock.type == "support");
    CHECK(rock.n == 1);
    CHECK(rock.m == 1);  // rocking: the two ends move opposite ways
    CHECK(free_body.classify(tilt, kLambda, kLambdaScale).type == "rigid");  // a spinning body's nutation

    // Sideways swinging: a translation along x.
    const ModeLabel swing = held.classify(
        shape_of(mesh, [](const std::array<double, 3>&) -> std::array<double, 3> { return {1, 0, 0}; }), kLambda,
        kLambdaScale);
    CHECK(swing.type == "support");
    CHECK(swing.n == 1);
    CHECK(swing.m == 0);

    // At zero frequency the old label stands: any mix of rigid motions.
    CHECK(held.classify(tilt, 1e-9 * kLambdaScale, kLambdaScale).type == "rigid");
}

TEST_CASE("Bending shapes stay bending: the rigid fit leaves far more than 5 % of them", "[classify]") {
    const Mesh& mesh = core_mesh();
    const ModeClassifier held(mesh, roll_nodes(mesh), BodyHeld::held);
    // A pinned half sine keeps 1 - 8 / pi^2 = 19 % of its mean square off
    // the best translation when the mean is taken along the length. The fit
    // weighs every looked-at node alike, and a hex20 mesh has more nodes on
    // its corner planes than on its mid planes, so the truth here is the
    // same fit by hand over the nodes: share = 1 - (sum s)^2 / (N sum s^2)
    // (a rotation cannot help: the shape is symmetric in z and around the
    // axis, so its moments about the centroid vanish). 24 % on this mesh.
    const auto half_sine = [](const std::array<double, 3>& x) -> std::array<double, 3> {
        return {0, std::sin(M_PI * x[2] / kLength), 0};
    };
    const std::vector<double> pinned = shape_of(mesh, half_sine);
    double sum = 0, sum_of_squares = 0;
    const std::vector<int> nodes = roll_nodes(mesh);
    for (int n : nodes) {
        const double s = std::sin(M_PI * mesh.nodes[n][2] / kLength);
        sum += s;
        sum_of_squares += s * s;
    }
    const double by_hand = 1 - sum * sum / (double(nodes.size()) * sum_of_squares);
    CHECK(by_hand > 1 - 8 / (M_PI * M_PI));  // the corner planes weigh the ends, where s is small
    CHECK(held.deformation_share(pinned) == Approx(by_hand).epsilon(1e-9));
    const ModeLabel label = held.classify(pinned, kLambda, kLambdaScale);
    CHECK(label.type == "bending");
    CHECK(label.n == 1);
    CHECK(label.m == 0);
    const auto free_free = [](const std::array<double, 3>& x) -> std::array<double, 3> {
        const double s = x[2] / kLength - 0.5;
        return {s * s - 1.0 / 12, 0, 0};  // orthogonal to 1 and s over the length
    };
    const std::vector<double> symmetric = shape_of(mesh, free_free);
    CHECK(held.deformation_share(symmetric) > 0.9);
    CHECK(held.classify(symmetric, kLambda, kLambdaScale).type == "bending");
}
