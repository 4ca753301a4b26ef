#include "output/side_by_side.hpp"

#include <cstdio>
#include <sstream>

namespace coremodal {

void print_side_by_side(std::ostream& out, const std::vector<ModeShift>& shifts) {
    out << "\nelastic chucks vs rigid clamps over the expanding elements (paired by type, n and order; m of the elastic run):\n";
    out << " type       n   m   elastic: mode  f [Hz]     rigid: mode  f [Hz]     shift\n";
    out << " ---------  --  --  -------------------  -------------------  --------\n";
    char line[256];
    for (const ModeShift& s : shifts) {
        const auto side = [](int index, double f) {
            char cell[64];
            if (index)
                std::snprintf(cell, sizeof cell, "%4d  %11.4f", index, f);
            else
                std::snprintf(cell, sizeof cell, "%4s  %11s", "-", "(not found)");
            return std::string(cell);
        };
        char shift[32] = "";
        if (s.elastic_index && s.rigid_index) std::snprintf(shift, sizeof shift, "%+7.2f %%", s.shift_percent());
        std::snprintf(line, sizeof line, " %-9s  %2d  %2d  %s    %s    %s\n", s.type.c_str(), s.n, s.m,
                      side(s.elastic_index, s.elastic_hz).c_str(), side(s.rigid_index, s.rigid_hz).c_str(), shift);
        out << line;
    }
}

std::string side_by_side_csv(const std::vector<ModeShift>& shifts) {
    std::ostringstream s;
    s.precision(10);
    s << "type,n,m,elastic_mode,elastic_hz,rigid_mode,rigid_hz,shift_percent\n";
    for (const ModeShift& r : shifts)
        s << r.type << ',' << r.n << ',' << r.m << ',' << r.elastic_index << ',' << r.elastic_hz << ','
          << r.rigid_index << ',' << r.rigid_hz << ',' << r.shift_percent() << '\n';
    return s.str();
}

}  // namespace coremodal
