// PCCD/IO/internal/ply_types.h -- the model of a PLY header that PCCD's PLY check builds
// (doc/manual/io.md, the PLY row of the format table): the eight scalar types with their names and
// sizes, the properties and elements a header declares, what the check found (Ply_summary), and a
// reader of the binary values of a body in either byte order. This header does not include CGAL.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace PCCD::IO::internal {

enum class Ply_type : unsigned char { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

inline std::optional<Ply_type> ply_type(std::string_view name) noexcept
{
    if (name == "char" || name == "int8") return Ply_type::int8;
    if (name == "uchar" || name == "uint8") return Ply_type::uint8;
    if (name == "short" || name == "int16") return Ply_type::int16;
    if (name == "ushort" || name == "uint16") return Ply_type::uint16;
    if (name == "int" || name == "int32") return Ply_type::int32;
    if (name == "uint" || name == "uint32") return Ply_type::uint32;
    if (name == "float" || name == "float32") return Ply_type::float32;
    if (name == "double" || name == "float64") return Ply_type::float64;
    return std::nullopt;
}

inline const char* ply_type_name(Ply_type type) noexcept
{
    static constexpr const char* names[] = {"char", "uchar", "short", "ushort", "int", "uint", "float", "double"};
    return names[static_cast<int>(type)];
}

inline std::size_t ply_size(Ply_type type) noexcept
{
    static constexpr std::size_t sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
    return sizes[static_cast<int>(type)];
}

inline bool ply_is_float(Ply_type type) noexcept { return type == Ply_type::float32 || type == Ply_type::float64; }

struct Ply_property {
    enum Role { other, coordinate, normal, face_indices };
    std::string name;
    Ply_type type = Ply_type::float64; // the item type of a list
    bool is_list = false;
    Ply_type count_type = Ply_type::uint8;
    Role role = other;
    int axis = 0; // 0, 1, 2 for x, y, z (or nx, ny, nz)
};

struct Ply_element {
    enum Kind { other, vertex, face };
    std::string name;
    std::uint64_t count = 0;
    std::size_t line = 0;
    std::vector<Ply_property> properties;
    Kind kind = other;
};

struct Ply_summary {
    std::size_t vertices = 0;
    std::size_t faces = 0;    // items of the face element (0 without one)
    bool normals = false;     // the vertex element has nx, ny, nz
    bool binary = false;
    bool face_indices = false; // the face element has a vertex_indices list CGAL reads (int or uint)
};

/// Reads the binary values of a PLY body, in either byte order.
class Ply_bytes {
public:
    Ply_bytes(std::string_view data, bool big_endian)
        : m_data(data), m_swap(big_endian != (std::endian::native == std::endian::big))
    {
    }
    std::size_t remaining() const noexcept { return m_data.size() - m_position; }
    void skip(std::size_t n) noexcept { m_position += n; }

    /// The next value of type `type` as a double (exact for every PLY type).
    double read(Ply_type type) noexcept
    {
        switch (type) {
        case Ply_type::int8: return static_cast<std::int8_t>(raw<std::uint8_t>());
        case Ply_type::uint8: return raw<std::uint8_t>();
        case Ply_type::int16: return static_cast<std::int16_t>(raw<std::uint16_t>());
        case Ply_type::uint16: return raw<std::uint16_t>();
        case Ply_type::int32: return static_cast<std::int32_t>(raw<std::uint32_t>());
        case Ply_type::uint32: return raw<std::uint32_t>();
        case Ply_type::float32: { // a NaN becomes a quiet NaN without a floating-point operation
            const std::uint32_t bits = raw<std::uint32_t>();
            if ((bits & 0x7F800000u) == 0x7F800000u && (bits & 0x007FFFFFu) != 0)
                return std::numeric_limits<double>::quiet_NaN();
            return std::bit_cast<float>(bits);
        }
        case Ply_type::float64: {
            const std::uint64_t bits = raw<std::uint64_t>();
            if ((bits & 0x7FF0000000000000u) == 0x7FF0000000000000u && (bits & 0x000FFFFFFFFFFFFFu) != 0)
                return std::numeric_limits<double>::quiet_NaN();
            return std::bit_cast<double>(bits);
        }
        }
        return 0;
    }

private:
    template <class U>
    U raw() noexcept
    {
        U value;
        std::memcpy(&value, m_data.data() + m_position, sizeof(U));
        m_position += sizeof(U);
        if (m_swap) {
            U swapped = 0;
            for (std::size_t b = 0; b < sizeof(U); ++b) swapped = static_cast<U>((swapped << 8) | ((value >> (8 * b)) & 0xFF));
            value = swapped;
        }
        return value;
    }

    std::string_view m_data;
    std::size_t m_position = 0;
    bool m_swap;
};

} // namespace PCCD::IO::internal
