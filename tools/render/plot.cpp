// tools/render/plot.cpp -- the profile plot of plot.h: a small rasterizer of lines, dots and bars.
#include "plot.h"

#include <PCCD/Error.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace pccd_render {
namespace {

struct Canvas {
    Image image;

    void set(int x, int y, Rgb c)
    {
        if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
        const std::size_t i = 3 * (std::size_t(y) * std::size_t(image.width) + std::size_t(x));
        image.rgb[i] = c.r;
        image.rgb[i + 1] = c.g;
        image.rgb[i + 2] = c.b;
    }

    /// A line of `thickness` pixels from (x0, y0) to (x1, y1), dashed in 8-pixel runs when asked.
    void line(double x0, double y0, double x1, double y1, Rgb c, int thickness = 1, bool dashed = false)
    {
        const double length = std::max(std::abs(x1 - x0), std::abs(y1 - y0));
        const int steps = std::max(1, int(std::ceil(length)));
        const int half = thickness / 2;
        for (int s = 0; s <= steps; ++s) {
            if (dashed && (s / 8) % 2 == 1) continue;
            const double t = double(s) / double(steps);
            const int x = int(std::lround(x0 + t * (x1 - x0))), y = int(std::lround(y0 + t * (y1 - y0)));
            for (int dx = -half; dx <= thickness - 1 - half; ++dx)
                for (int dy = -half; dy <= thickness - 1 - half; ++dy) set(x + dx, y + dy, c);
        }
    }

    void dot(double cx, double cy, double radius, Rgb c)
    {
        const int r = int(std::ceil(radius));
        for (int dy = -r; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx)
                if (dx * dx + dy * dy <= radius * radius) set(int(std::lround(cx)) + dx, int(std::lround(cy)) + dy, c);
    }
};

} // namespace

int plot_margin(int width, int height) { return std::max(8, std::min(width, height) / 16); }

double plot_x(std::size_t i, std::size_t n, int width, int height)
{
    const int m = plot_margin(width, height);
    return m + double(i) * double(width - 1 - 2 * m) / double(n > 1 ? n - 1 : 1);
}

double plot_y(double y, double y_max, int width, int height)
{
    const int m = plot_margin(width, height);
    const double clamped = std::isnan(y) ? 0.0 : std::clamp(y, 0.0, y_max);
    return double(height - 1 - m) - clamped / y_max * double(height - 1 - 2 * m);
}

Image plot_profile(const Profile_plot& plot, int width, int height)
{
    if (width < 16 || height < 16 || width > 8192 || height > 8192)
        throw PCCD::Invalid_input("plot: the size " + std::to_string(width) + "x" + std::to_string(height) +
                                  " is not within [16, 8192] on each side");
    if (!(std::isfinite(plot.y_max) && plot.y_max > 0.0)) throw PCCD::Invalid_input("plot: y_max must be finite and > 0");
    const std::size_t n = plot.values.size();
    if (!plot.dot_colours.empty() && plot.dot_colours.size() != n)
        throw PCCD::Invalid_input("plot: one dot colour per value expected");
    if (plot.lower.size() != plot.upper.size() || (!plot.lower.empty() && plot.lower.size() != n))
        throw PCCD::Invalid_input("plot: the interval bars need one lower and one upper end per value");
    Canvas c;
    c.image.width = width;
    c.image.height = height;
    c.image.rgb.assign(3 * std::size_t(width) * std::size_t(height), 255);
    const int m = plot_margin(width, height);
    const auto x_of = [&](std::size_t i) { return plot_x(i, n, width, height); };
    const auto y_of = [&](double y) { return plot_y(y, plot.y_max, width, height); };
    const double dot_radius = std::clamp(double(width - 2 * m) / double(std::max<std::size_t>(n, 1)) / 3.0, 1.5, 4.0);

    for (std::size_t i = 0; i < plot.lower.size(); ++i)
        if (!std::isnan(plot.lower[i]) && !std::isnan(plot.upper[i]))
            c.line(x_of(i), y_of(plot.lower[i]), x_of(i), y_of(plot.upper[i]), plot.bar_colour, 3);
    // axes: the value 0 and the left edge
    c.line(m, height - 1 - m, width - 1 - m, height - 1 - m, plot.axis_colour);
    c.line(m, height - 1 - m, m, m, plot.axis_colour);
    for (const Profile_plot::Level& level : plot.levels)
        if (level.value >= 0.0 && level.value <= plot.y_max)
            c.line(m, y_of(level.value), width - 1 - m, y_of(level.value), level.colour, 1, level.dashed);
    if (plot.marker && *plot.marker < n) c.line(x_of(*plot.marker), m, x_of(*plot.marker), height - 1 - m, plot.marker_colour, 1, true);
    for (std::size_t i = 0; i + 1 < n; ++i)
        if (!std::isnan(plot.values[i]) && !std::isnan(plot.values[i + 1]))
            c.line(x_of(i), y_of(plot.values[i]), x_of(i + 1), y_of(plot.values[i + 1]), plot.line_colour, 2);
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isnan(plot.values[i]))
            c.dot(x_of(i), y_of(plot.values[i]), dot_radius, plot.dot_colours.empty() ? plot.line_colour : plot.dot_colours[i]);
    return std::move(c.image);
}

} // namespace pccd_render
