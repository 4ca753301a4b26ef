#include "scene/web_springs.hpp"

#include "common/format.hpp"

namespace coremodal {

WebSprings web_springs(const WebSpec& w) {
    return {w.modulus * w.thickness / w.span, w.tension / w.span, (w.shear_modulus * w.thickness + w.tension) / w.span};
}

std::vector<std::string> web_assumptions(const WebSpec& web) {
    const WebSprings k = web_springs(web);
    const auto per_area = [](double v) { return significant(v) + " N/m^2"; };
    return {"[web] the span acts on the web's line of the roll surface as springs per unit length: along the web "
            "E t / s = " + per_area(k.along) + " (its stretch), across it T / s = " + per_area(k.across) +
                " (a string), along the axis (G t + T) / s = " + per_area(k.axial) + " (its shear; G from " +
                web.shear_source + ")",
            "[web] left out: the web's bending stiffness, the span's mass and the tension's steady side pull on "
            "the roll (docs/theory/web.md)"};
}

}  // namespace coremodal
