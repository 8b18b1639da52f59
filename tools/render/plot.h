// tools/render/plot.h -- a profile plot for the pccd tool (`pccd clearance --png`): one value per
// index (e.g. the clearance at each pose of a path) drawn as a polyline with a dot per index, an
// interval bar around each value, horizontal reference levels (the margin, the cap) and a vertical
// marker (the first pose below the margin), into an Image written by write_png(). No text: the
// tool prints what each colour means. Tool code, not part of the library.
//
// Conventions: index i sits at x = left + i * (plot width) / max(1, n - 1); value 0 at the bottom
// edge of the plot area, y_max at its top. Pixel (0, 0) is the top-left corner.
#pragma once

#include "render.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace pccd_render {

/// What a profile plot shows.
struct Profile_plot {
    /// One value per index: finite values are drawn (clamped to [0, y_max]); +infinity is drawn at
    /// the top edge (e.g. "beyond the cap"); NaN is not drawn and breaks the polyline.
    std::vector<double> values;
    /// One colour per index for its dot (empty: line_colour).
    std::vector<Rgb> dot_colours;
    /// Optional interval bars [lower[i], upper[i]] (both empty, or one entry per index; non-finite
    /// ends are clamped to the plot).
    std::vector<double> lower;
    std::vector<double> upper;
    /// Horizontal lines at these values (drawn when within [0, y_max]).
    struct Level {
        double value;
        Rgb colour;
        bool dashed = false;
    };
    std::vector<Level> levels;
    /// A vertical line at this index, if any.
    std::optional<std::size_t> marker;
    Rgb marker_colour = colour_curve;
    /// The value at the top of the plot area; > 0 and finite.
    double y_max = 1.0;
    Rgb line_colour = colour_a;
    Rgb bar_colour{170, 200, 235};
    Rgb axis_colour{60, 60, 60};
};

/// The plot area's pixel margin on every side of a plot of `width` x `height`.
int plot_margin(int width, int height);

/// The pixel column of index `i` of `n` and the pixel row of value `y` in a plot of `width` x
/// `height` with the given y_max (the mapping plot_profile() draws with).
double plot_x(std::size_t i, std::size_t n, int width, int height);
double plot_y(double y, double y_max, int width, int height);

/// Draws `plot` on a white `width` x `height` image (each in [16, 8192]).
/// \throws PCCD::Invalid_input for a bad size, y_max not finite and > 0, or per-index vectors of
///         the wrong length.
Image plot_profile(const Profile_plot& plot, int width, int height);

} // namespace pccd_render
