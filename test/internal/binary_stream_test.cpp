// Tests of PCCD/internal/binary_stream.h, the binary reader and writer of the geodesic and object
// files: the exact bytes of the little-endian encoding of known integers and doubles (an encoder
// that copied the values' memory would give them reversed on a big-endian host and fail here), the
// checksum, and the size checks of the reader and writer. test_serialized_files loads committed
// files.
#include <PCCD/Error.h>
#include <PCCD/internal/binary_stream.h>

#include <catch2/catch.hpp>

#include "byte_helpers.h"

#include <bit>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

using pccd_test::bytes_of;

namespace {

using PCCD::internal::decode_little_endian;
using PCCD::internal::encode_little_endian;

template <class T>
std::vector<unsigned> encoded(T value)
{
    unsigned char bytes[sizeof(T)];
    encode_little_endian(value, bytes);
    return {bytes, bytes + sizeof(T)};
}

} // namespace

TEST_CASE("binary values are stored little-endian whatever the host", "[io]")
{
    using V = std::vector<unsigned>;
    CHECK(encoded(std::uint64_t{0x0102030405060708}) == V{0x08, 0x07, 0x06, 0x05, 0x04, 0x03, 0x02, 0x01});
    CHECK(encoded(std::uint32_t{0x01020304}) == V{0x04, 0x03, 0x02, 0x01});
    CHECK(encoded(std::uint16_t{0x0102}) == V{0x02, 0x01});
    CHECK(encoded(std::uint8_t{0xAB}) == V{0xAB});
    CHECK(encoded(std::int32_t{-2}) == V{0xFE, 0xFF, 0xFF, 0xFF});
    CHECK(encoded(std::int64_t{-256}) == V{0x00, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF});
    CHECK(encoded(1.0) == V{0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF0, 0x3F});
    CHECK(encoded(-2.5) == V{0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x04, 0xC0});
    CHECK(encoded(1.0 / 3.0) == V{0x55, 0x55, 0x55, 0x55, 0x55, 0x55, 0xD5, 0x3F});
    CHECK(encoded(1.0f) == V{0x00, 0x00, 0x80, 0x3F});
    CHECK(encoded(0.1f) == V{0xCD, 0xCC, 0xCC, 0x3D});

    const unsigned char bytes[8] = {0x08, 0x07, 0x06, 0x05, 0x04, 0x03, 0x02, 0x01};
    CHECK(decode_little_endian<std::uint64_t>(bytes) == 0x0102030405060708u);
    CHECK(decode_little_endian<std::uint32_t>(bytes) == 0x05060708u);
    CHECK(decode_little_endian<std::uint16_t>(bytes) == 0x0708u);
    const unsigned char minus_two[4] = {0xFE, 0xFF, 0xFF, 0xFF};
    CHECK(decode_little_endian<std::int32_t>(minus_two) == -2);
    const unsigned char minus_two_and_a_half[8] = {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x04, 0xC0};
    CHECK(decode_little_endian<double>(minus_two_and_a_half) == -2.5);

    // Every double comes back bit for bit, a signaling NaN's payload included.
    for (const std::uint64_t bits : {std::uint64_t{0x7FF0000000000001}, std::uint64_t{0xFFF8000000000123},
                                     std::uint64_t{0x8000000000000000}, std::uint64_t{0x0000000000000001},
                                     std::uint64_t{0x7FEFFFFFFFFFFFFF}}) {
        unsigned char out[8];
        encode_little_endian(std::bit_cast<double>(bits), out);
        CHECK(std::bit_cast<std::uint64_t>(decode_little_endian<double>(out)) == bits);
    }
}

TEST_CASE("the binary writer and reader agree and check sizes", "[io]")
{
    PCCD::internal::Binary_writer out;
    const char magic[4] = {'A', 'B', 'C', '\0'};
    out.write(magic, sizeof magic);
    out.put(std::uint32_t{0x01020304});
    out.put(std::vector<std::uint16_t>{0x0102, 0x0304});
    const std::vector<double> values = {1.0, -2.5};
    out.write(values.data(), sizeof(double) * values.size());
    out.finish();
    const std::string& bytes = out.bytes();
    REQUIRE(bytes.size() == 4 + 4 + 4 + 16 + 8);
    CHECK(bytes_of(bytes, 0, 12) == std::vector<unsigned>{'A', 'B', 'C', 0, 0x04, 0x03, 0x02, 0x01, 0x02, 0x01, 0x04, 0x03});
    CHECK(bytes_of(bytes, 20, 8) == std::vector<unsigned>{0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x04, 0xC0});

    // The checksum: FNV-1a over the little-endian 64-bit words, the tail zero-padded.
    PCCD::internal::Word_checksum sum;
    const unsigned char ten[10] = {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x09, 0x0A};
    sum.update(ten, 3);
    sum.update(ten + 3, 7);
    CHECK(sum.value() == 0xf71913fd280a2cdfu);

    for (const bool from_stream : {false, true}) {
        std::istringstream stream(bytes);
        PCCD::internal::Binary_reader in = from_stream ? PCCD::internal::Binary_reader(stream, bytes.size(), "mem", "p: ")
                                                       : PCCD::internal::Binary_reader(bytes, "mem", "p: ");
        char back[4];
        in.read(back, sizeof back);
        CHECK(std::string(back, 3) == "ABC");
        CHECK(in.get<std::uint32_t>() == 0x01020304u);
        CHECK(in.get_vector<std::uint16_t>(2) == std::vector<std::uint16_t>{0x0102, 0x0304});
        CHECK(in.position() == 12);
        CHECK(in.remaining() == 24);
        std::vector<double> doubles(2);
        in.read(doubles.data(), sizeof(double) * 2);
        CHECK(doubles == values);
        in.check_sum();
        CHECK(in.remaining() == 0);
        REQUIRE_THROWS_WITH(in.get<std::uint8_t>(), Catch::Contains("mem") && Catch::Contains("p: truncated file"));
    }

    // A corrupted byte fails the checksum; a count larger than the rest fails before allocating.
    std::string corrupted = bytes;
    corrupted[5] = char(corrupted[5] ^ 0x10);
    PCCD::internal::Binary_reader bad(corrupted, "bad");
    std::vector<char> all(corrupted.size() - 8);
    bad.read(all.data(), all.size());
    REQUIRE_THROWS_AS(bad.check_sum(), PCCD::File_error);
    PCCD::internal::Binary_reader huge(bytes, "huge");
    REQUIRE_THROWS_WITH(huge.get_vector<double>(std::uint64_t{1} << 60), Catch::Contains("truncated file"));
    // Sizes that are not a whole number of values are a programming error.
    double one = 1.0;
    REQUIRE_THROWS_AS(out.write(&one, 7), PCCD::Invalid_input);
    PCCD::internal::Binary_reader odd(bytes, "odd");
    REQUIRE_THROWS_AS(odd.read(&one, 3), PCCD::Invalid_input);
}

TEST_CASE("a section written through a stream counts in the enclosing writer's checksum", "[io]")
{
    // The same bytes, once written directly and once by another writer into write_section()'s
    // stream (as the geodesic section of an object file is), give the same file, checksum included.
    const std::vector<std::uint32_t> values = {7, 0xFFFFFFFF, 0x01020304};
    PCCD::internal::Binary_writer inner_alone;
    inner_alone.put(values);
    inner_alone.put(std::uint8_t{9});
    inner_alone.finish(); // the section's own checksum is part of the section
    PCCD::internal::Binary_writer direct;
    direct.put(std::uint16_t{0xABCD});
    direct.write(inner_alone.bytes().data(), inner_alone.bytes().size());
    direct.write("xy", 2);
    direct.put(std::uint8_t{0x5A});
    direct.finish();

    for (const bool to_stream : {false, true}) {
        std::ostringstream file(std::ios::binary);
        PCCD::internal::Binary_writer sectioned =
            to_stream ? PCCD::internal::Binary_writer(file, "file") : PCCD::internal::Binary_writer();
        sectioned.put(std::uint16_t{0xABCD});
        const std::uint64_t written = sectioned.write_section([&](std::ostream& section) {
            PCCD::internal::Binary_writer inner(section, "section");
            inner.put(values);
            inner.put(std::uint8_t{9});
            inner.finish();
        });
        CHECK(written == inner_alone.bytes().size());
        // Characters one at a time take the stream buffer's other path.
        CHECK(sectioned.write_section([](std::ostream& section) { section.put('x').put('y'); }) == 2);
        sectioned.put(std::uint8_t{0x5A});
        sectioned.finish();
        CHECK((to_stream ? file.str() : sectioned.bytes()) == direct.bytes());
    }
}
