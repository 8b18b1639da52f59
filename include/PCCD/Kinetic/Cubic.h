// PCCD/Kinetic/Cubic.h -- one coordinate of one piece of a flightplan: a polynomial of degree <= 3
// in the time since the piece's origin (doc/manual/kinetic.md, "Flightplans"). The shipped
// flightplans return it from piece_cubic(), the piece interface that next_crossing (next_crossing.h)
// reads and Polynomial_flightplan::from_pieces converts.
#pragma once

#include <array>
#include <cstddef>

namespace PCCD {

/// c[0] + c[1] u + c[2] u^2 + c[3] u^3, u = time minus an origin stored next to it.
struct Cubic {
    std::array<double, 4> c{0.0, 0.0, 0.0, 0.0};

    double operator()(double u) const { return ((c[3] * u + c[2]) * u + c[1]) * u + c[0]; }

    /// The same polynomial in v = u - delta (Taylor shift), i.e. expanded around origin + delta.
    Cubic shifted(double delta) const
    {
        if (delta == 0.0) return *this;
        Cubic s;
        s.c[0] = (*this)(delta);
        s.c[1] = (3.0 * c[3] * delta + 2.0 * c[2]) * delta + c[1];
        s.c[2] = 3.0 * c[3] * delta + c[2];
        s.c[3] = c[3];
        return s;
    }

    friend Cubic operator-(const Cubic& a, const Cubic& b)
    {
        Cubic d;
        for (std::size_t i = 0; i < 4; ++i) d.c[i] = a.c[i] - b.c[i];
        return d;
    }

    int degree() const
    {
        for (int i = 3; i >= 0; --i)
            if (c[std::size_t(i)] != 0.0) return i;
        return -1;
    }
};

} // namespace PCCD
