// PCCD/internal/binary_stream.h -- the one binary reader and writer of PCCD's own files: the
// geodesic file of write_geodesic_data (doc/manual/graphs.md, "Saving and loading") and the object
// file of Point_cloud_object::save (doc/manual/surface.md, the paragraph on save and load). Every
// integer and every IEEE-754 float and double is stored little-endian whatever the host's byte
// order: encode_little_endian and decode_little_endian go byte by byte through shifts of the
// value's bits, never through a copy of its memory. Also the checksum both formats end with
// (FNV-1a over the file's little-endian 64-bit words). The reader checks sizes before it copies or
// allocates; a short read is a File_error "truncated file", a failed write a File_error "write
// failed (disk full?)", both naming the file.
#pragma once

#include <PCCD/Error.h>

#include <algorithm>
#include <bit>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <istream>
#include <limits>
#include <ostream>
#include <streambuf>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace PCCD::internal {

/// The byte-order mark of PCCD's binary files, stored after their magic: read back as another value,
/// the file was written on a machine of another byte order.
inline constexpr std::uint32_t byte_order_mark = 0x01020304;

/// The values the binary files store: integers of 1, 2, 4 or 8 bytes (not bool), and IEEE-754
/// float and double.
template <class T>
concept Binary_value =
    (std::is_integral_v<T> && !std::is_same_v<T, bool> &&
     (sizeof(T) == 1 || sizeof(T) == 2 || sizeof(T) == 4 || sizeof(T) == 8)) ||
    ((std::is_same_v<T, float> || std::is_same_v<T, double>) && std::numeric_limits<T>::is_iec559);

/// The unsigned integer of `Size` bytes.
template <std::size_t Size>
using Unsigned_of_size =
    std::conditional_t<Size == 1, std::uint8_t,
                       std::conditional_t<Size == 2, std::uint16_t,
                                          std::conditional_t<Size == 4, std::uint32_t, std::uint64_t>>>;

/// Stores `value` in the sizeof(T) bytes at `out`, least significant byte first (a float or double
/// as its IEEE-754 bits), on any host.
template <Binary_value T>
constexpr void encode_little_endian(T value, unsigned char* out) noexcept
{
    using U = Unsigned_of_size<sizeof(T)>;
    const U bits = std::bit_cast<U>(value);
    for (std::size_t b = 0; b < sizeof(T); ++b) out[b] = static_cast<unsigned char>(bits >> (8 * b));
}

/// The value stored by encode_little_endian in the sizeof(T) bytes at `in`, on any host. Raises no
/// floating-point exception, and gives a NaN's bits back unchanged.
template <Binary_value T>
constexpr T decode_little_endian(const unsigned char* in) noexcept
{
    using U = Unsigned_of_size<sizeof(T)>;
    U bits = 0;
    for (std::size_t b = 0; b < sizeof(T); ++b)
        bits = static_cast<U>(bits | static_cast<U>(static_cast<U>(in[b]) << (8 * b)));
    return std::bit_cast<T>(bits);
}

/// decode_little_endian of bytes held as char.
template <Binary_value T>
T decode_little_endian(const char* in) noexcept
{
    return decode_little_endian<T>(reinterpret_cast<const unsigned char*>(in));
}

/// FNV-1a over the little-endian 64-bit words of a byte sequence (fast enough for gigabyte files);
/// the tail is zero-padded. The same value on every host.
class Word_checksum {
public:
    void update(const void* data, std::size_t size)
    {
        const auto* bytes = static_cast<const unsigned char*>(data);
        while (size > 0) {
            const std::size_t take = std::min<std::size_t>(size, 8 - m_fill);
            std::memcpy(m_buffer + m_fill, bytes, take);
            m_fill += take;
            bytes += take;
            size -= take;
            if (m_fill == 8) flush();
        }
    }
    /// The checksum of everything given so far (pads the tail: give nothing more afterwards).
    std::uint64_t value()
    {
        if (m_fill > 0) {
            std::memset(m_buffer + m_fill, 0, 8 - m_fill);
            flush();
        }
        return m_hash;
    }

private:
    void flush()
    {
        m_hash = (m_hash ^ decode_little_endian<std::uint64_t>(m_buffer)) * 0x100000001b3ull;
        m_fill = 0;
    }
    std::uint64_t m_hash = 0xcbf29ce484222325ull;
    unsigned char m_buffer[8] = {};
    std::size_t m_fill = 0;
};

/// \throws Invalid_input unless `size` bytes are a whole number of `value_size`-byte values.
inline void check_whole_values(const char* who, std::size_t size, std::size_t value_size)
{
    if (size % value_size != 0)
        throw Invalid_input(concat(who, ": ", size, " bytes are not a whole number of ", value_size, "-byte values"));
}

/// Writes values little-endian, into memory or to a stream, and keeps the checksum of all it wrote.
class Binary_writer {
public:
    /// Into memory: bytes() holds what was written.
    Binary_writer() = default;
    /// To `out`; `file` names it in the File_error of a failed write.
    Binary_writer(std::ostream& out, std::string file) : m_out(&out), m_file(std::move(file)) {}

    template <Binary_value T>
    void put(T value)
    {
        unsigned char bytes[sizeof(T)];
        encode_little_endian(value, bytes);
        emit(bytes, sizeof bytes);
    }
    /// Every element of `values`, in order (no count).
    template <Binary_value T>
    void put(const std::vector<T>& values)
    {
        write(values.data(), values.size() * sizeof(T));
    }
    /// The values at `values` that make up `size` bytes (counted as std::ostream::write counts, a
    /// whole number of values; Invalid_input otherwise), each as put() writes it.
    template <Binary_value T>
    void write(const T* values, std::size_t size)
    {
        check_whole_values("Binary_writer::write", size, sizeof(T));
        constexpr std::size_t per_chunk = 4096 / sizeof(T);
        unsigned char chunk[per_chunk * sizeof(T)];
        const std::size_t count = size / sizeof(T);
        for (std::size_t first = 0; first < count; first += per_chunk) {
            const std::size_t n = std::min(per_chunk, count - first);
            for (std::size_t i = 0; i < n; ++i) encode_little_endian(values[first + i], chunk + i * sizeof(T));
            emit(chunk, n * sizeof(T));
        }
    }
    /// Appends the checksum (u64) of everything written before, then flushes a stream. Write
    /// nothing afterwards.
    void finish()
    {
        unsigned char sum[8];
        encode_little_endian(m_checksum.value(), sum);
        append(sum, sizeof sum);
        if (m_out) {
            m_out->flush();
            if (!*m_out) throw File_error(m_file, "write failed (disk full?)");
        }
    }
    /// What was written, when writing into memory.
    const std::string& bytes() const noexcept { return m_bytes; }

    /// Calls `write` with a std::ostream whose bytes go where this writer's go, in order, and count
    /// in this writer's checksum: a section written by a function that writes to a stream (the
    /// geodesic section of an object file), without holding it in memory first. Returns the number
    /// of bytes `write` wrote.
    template <class Write>
    std::uint64_t write_section(Write&& write)
    {
        Section_buffer buffer(*this);
        std::ostream section(&buffer);
        section.exceptions(std::ios::badbit); // a failed write of this writer reaches the caller
        write(section);
        section.flush();
        return buffer.count();
    }

private:
    /// The stream buffer of write_section(): unbuffered, every byte through emit().
    class Section_buffer : public std::streambuf {
    public:
        explicit Section_buffer(Binary_writer& writer) : m_writer(writer) {}
        std::uint64_t count() const noexcept { return m_count; }

    protected:
        std::streamsize xsputn(const char* data, std::streamsize size) override
        {
            m_writer.emit(reinterpret_cast<const unsigned char*>(data), std::size_t(size));
            m_count += std::uint64_t(size);
            return size;
        }
        int_type overflow(int_type c) override
        {
            if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
            const auto byte = static_cast<unsigned char>(traits_type::to_char_type(c));
            m_writer.emit(&byte, 1);
            ++m_count;
            return c;
        }

    private:
        Binary_writer& m_writer;
        std::uint64_t m_count = 0;
    };

    void emit(const unsigned char* data, std::size_t size)
    {
        m_checksum.update(data, size);
        append(data, size);
    }
    void append(const unsigned char* data, std::size_t size)
    {
        if (!m_out) {
            m_bytes.append(reinterpret_cast<const char*>(data), size);
            return;
        }
        m_out->write(reinterpret_cast<const char*>(data), std::streamsize(size));
        if (!*m_out) throw File_error(m_file, "write failed (disk full?)");
    }

    std::ostream* m_out = nullptr;
    std::string m_file;
    std::string m_bytes;
    Word_checksum m_checksum;
};

/// Reads values written by Binary_writer, from a stream or from bytes in memory, and keeps the
/// checksum of all it read. Errors are File_error(file, prefix + problem).
class Binary_reader {
public:
    /// The `size` bytes that follow in `in`.
    Binary_reader(std::istream& in, std::uint64_t size, std::string file, std::string prefix = {})
        : m_in(&in), m_size(size), m_file(std::move(file)), m_prefix(std::move(prefix))
    {
    }
    /// `bytes`, read in place: they must outlive the reader.
    Binary_reader(std::string_view bytes, std::string file, std::string prefix = {})
        : m_bytes(bytes), m_size(bytes.size()), m_file(std::move(file)), m_prefix(std::move(prefix))
    {
    }

    template <Binary_value T>
    T get()
    {
        unsigned char bytes[sizeof(T)];
        read_bytes(bytes, sizeof bytes);
        return decode_little_endian<T>(bytes);
    }
    /// `count` values; "truncated file" before allocating them if fewer bytes remain.
    template <Binary_value T>
    std::vector<T> get_vector(std::uint64_t count)
    {
        if (count > remaining() / sizeof(T)) fail("truncated file");
        std::vector<T> values(static_cast<std::size_t>(count));
        read(values.data(), values.size() * sizeof(T));
        return values;
    }
    /// Into `values`, the values that make up the next `size` bytes (a whole number of values;
    /// Invalid_input otherwise).
    template <Binary_value T>
    void read(T* values, std::size_t size)
    {
        check_whole_values("Binary_reader::read", size, sizeof(T));
        if (size == 0) return; // an empty array's data() may be null
        auto* bytes = reinterpret_cast<unsigned char*>(values);
        read_bytes(bytes, size);
        for (std::size_t i = 0; i < size / sizeof(T); ++i) values[i] = decode_little_endian<T>(bytes + i * sizeof(T));
    }
    /// Reads the stored checksum (u64) and compares it with that of everything read before.
    void check_sum()
    {
        const std::uint64_t expected = m_checksum.value();
        unsigned char stored[8];
        read_raw(stored, sizeof stored);
        if (decode_little_endian<std::uint64_t>(stored) != expected) fail("checksum mismatch: the file is corrupted");
    }
    std::uint64_t remaining() const noexcept { return m_size - m_position; }
    std::uint64_t position() const noexcept { return m_position; }
    [[noreturn]] void fail(const std::string& problem) const { throw File_error(m_file, m_prefix + problem); }

private:
    void read_bytes(unsigned char* out, std::size_t size)
    {
        read_raw(out, size);
        m_checksum.update(out, size);
    }
    void read_raw(unsigned char* out, std::size_t size)
    {
        if (m_in) {
            m_in->read(reinterpret_cast<char*>(out), std::streamsize(size));
            if (std::size_t(m_in->gcount()) != size) fail("truncated file");
        } else {
            if (remaining() < size) fail("truncated file");
            if (size > 0) std::memcpy(out, m_bytes.data() + m_position, size);
        }
        m_position += size;
    }

    std::istream* m_in = nullptr;
    std::string_view m_bytes;
    std::uint64_t m_size = 0;
    std::uint64_t m_position = 0;
    std::string m_file, m_prefix;
    Word_checksum m_checksum;
};

} // namespace PCCD::internal
