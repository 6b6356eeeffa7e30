#include "scene/io/FormatChecks.h"

#include "util/Error.h"
#include "util/InputFiles.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::scene::io {

namespace fs = std::filesystem;

namespace {

std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        const std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

std::string hexByte(char c) {
    static const char* digits = "0123456789ABCDEF";
    const auto b = static_cast<unsigned char>(c);
    return std::string("0x") + digits[b >> 4] + digits[b & 15];
}

template <typename T>
bool parseWhole(std::string_view s, T& value) {
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    return ec == std::errc() && end == s.data() + s.size();
}

// ---- PLY ----

struct PlyType {
    int size;
    bool isSigned, isFloat;
};

const std::map<std::string_view, PlyType>& plyTypes() {
    static const std::map<std::string_view, PlyType> types = {
        {"char", {1, true, false}},   {"uchar", {1, false, false}},  {"int8", {1, true, false}},    {"uint8", {1, false, false}},
        {"short", {2, true, false}},  {"ushort", {2, false, false}}, {"int16", {2, true, false}},   {"uint16", {2, false, false}},
        {"int", {4, true, false}},    {"uint", {4, false, false}},   {"int32", {4, true, false}},   {"uint32", {4, false, false}},
        {"float", {4, true, true}},   {"float32", {4, true, true}},  {"double", {8, true, true}},   {"float64", {8, true, true}}};
    return types;
}

struct PlyProperty {
    std::string name;
    PlyType item;
    bool list = false;
    PlyType count{};  // lists: the type of the length before the items
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    int line = 0;
    std::vector<PlyProperty> properties;
};

struct PlyHeader {
    enum class Format { None, Ascii, LittleEndian, BigEndian } format = Format::None;
    std::vector<PlyElement> elements;
    std::size_t dataStart = 0;  // byte offset of the first data byte
    int dataLine = 0;           // line number of the first data line
};

class PlyChecker {
public:
    PlyChecker(const fs::path& file, const std::string& data) : file_(file), data_(data) {}

    void check() {
        const PlyHeader h = header();
        if (h.format == PlyHeader::Format::Ascii) asciiData(h);
        else binaryData(h);
    }

private:
    [[noreturn]] void fail(int line, const std::string& what) const { throw InputError(file_, line, what); }

    // Next line (without '\n' or '\r'), or false at the end of the file.
    bool nextLine(std::size_t& pos, std::string_view& line) const {
        if (pos >= data_.size()) return false;
        std::size_t end = data_.find('\n', pos);
        const std::size_t next = end == std::string::npos ? data_.size() : end + 1;
        if (end == std::string::npos) end = data_.size();
        line = std::string_view(data_).substr(pos, end - pos);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        pos = next;
        return true;
    }

    PlyHeader header() const {
        PlyHeader h;
        std::size_t pos = 0;
        std::string_view line;
        int number = 1;
        if (!nextLine(pos, line) || line != "ply") fail(1, "not a PLY file: the first line must be 'ply'");
        while (nextLine(pos, line)) {
            ++number;
            // Words are separated by spaces and tabs. Assimp 5.2 loops forever on an
            // "end_header" followed by a vertical tab (tests/fuzz), so no other control
            // character may stand in a header line.
            for (const char c : line)
                if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f)
                    fail(number, "control character " + hexByte(c) + " in the PLY header (only spaces and tabs separate words)");
            const auto w = words(line);
            if (w.empty()) fail(number, "empty line in the PLY header");
            if (w[0] == "comment" || w[0] == "obj_info") continue;
            if (w[0] == "end_header") {
                if (w.size() != 1) fail(number, "'end_header' takes nothing after it");
                // Assimp 5.2 loops forever looking for the line's end (tests/fuzz).
                if (data_[pos - 1] != '\n') fail(number, "truncated PLY: 'end_header' must end with a line break");
                if (h.format == PlyHeader::Format::None) fail(number, "the PLY header has no 'format' line");
                h.dataStart = pos;
                h.dataLine = number + 1;
                return h;
            }
            if (w[0] == "format") format(w, number, h);
            else if (w[0] == "element") element(w, number, h);
            else if (w[0] == "property") property(w, number, h);
            else fail(number, "unknown PLY header line '" + std::string(w[0]) + "' (expected format, element, property, comment or end_header)");
        }
        fail(number, "truncated PLY: the header has no 'end_header' line");
    }

    void format(const std::vector<std::string_view>& w, int number, PlyHeader& h) const {
        if (h.format != PlyHeader::Format::None || !h.elements.empty()) fail(number, "'format' must come once, before the elements");
        if (w.size() != 3 || w[2] != "1.0") fail(number, "the format line must read 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
        if (w[1] == "ascii") h.format = PlyHeader::Format::Ascii;
        else if (w[1] == "binary_little_endian") h.format = PlyHeader::Format::LittleEndian;
        else if (w[1] == "binary_big_endian") h.format = PlyHeader::Format::BigEndian;
        else fail(number, "unknown PLY format '" + std::string(w[1]) + "'");
    }

    void element(const std::vector<std::string_view>& w, int number, PlyHeader& h) const {
        if (h.format == PlyHeader::Format::None) fail(number, "'element' before the 'format' line");
        if (!h.elements.empty() && h.elements.back().properties.empty())
            fail(h.elements.back().line, "element '" + h.elements.back().name + "' has no properties");
        PlyElement e;
        if (w.size() != 3 || !parseWhole(w[2], e.count) || e.count > 0xffffffffull)
            fail(number, "an element line must read 'element <name> <count>' with a count from 0 to 4294967295");
        e.name = std::string(w[1]);
        e.line = number;
        // Assimp 5.2 writes past its vertex array when "vertex" comes twice (tests/fuzz, under
        // valgrind); no real file repeats a name.
        for (const PlyElement& other : h.elements)
            if (other.name == e.name) fail(number, "element '" + e.name + "' is declared twice (first on line " + std::to_string(other.line) + ")");
        h.elements.push_back(std::move(e));
    }

    void property(const std::vector<std::string_view>& w, int number, PlyHeader& h) const {
        if (h.elements.empty()) fail(number, "'property' before any 'element'");
        const auto& types = plyTypes();
        PlyProperty p;
        if (w.size() == 3 && w[1] != "list") {
            const auto it = types.find(w[1]);
            if (it == types.end()) fail(number, "unknown property type '" + std::string(w[1]) + "'");
            p.item = it->second;
        } else if (w.size() == 5 && w[1] == "list") {
            const auto count = types.find(w[2]), item = types.find(w[3]);
            if (count == types.end() || count->second.isFloat) fail(number, "a list's length type must be an integer type, not '" + std::string(w[2]) + "'");
            if (item == types.end()) fail(number, "unknown property type '" + std::string(w[3]) + "'");
            p.list = true;
            p.count = count->second;
            p.item = item->second;
        } else {
            fail(number, "a property line must read 'property <type> <name>' or 'property list <type> <type> <name>'");
        }
        p.name = std::string(w.back());
        for (const PlyProperty& other : h.elements.back().properties)
            if (other.name == p.name) fail(number, "property '" + p.name + "' of element '" + h.elements.back().name + "' is declared twice");
        h.elements.back().properties.push_back(p);
    }

    // Binary: walks every instance (list lengths included) and fails where the data runs out.
    void binaryData(const PlyHeader& h) const {
        const bool little = h.format == PlyHeader::Format::LittleEndian;
        std::size_t pos = h.dataStart;
        const std::size_t size = data_.size();
        for (const PlyElement& e : h.elements) {
            std::uint64_t fixed = 0;
            bool lists = false;
            for (const PlyProperty& p : e.properties) {
                lists = lists || p.list;
                if (!p.list) fixed += static_cast<std::uint64_t>(p.item.size);
            }
            if (!lists) {  // fixed-size instances: one comparison
                if (e.count * fixed > size - pos) truncatedBinary(e, 0, size - pos);
                pos += static_cast<std::size_t>(e.count * fixed);
                continue;
            }
            for (std::uint64_t i = 0; i < e.count; ++i)
                for (const PlyProperty& p : e.properties) {
                    if (!p.list) {
                        if (static_cast<std::size_t>(p.item.size) > size - pos) truncatedBinary(e, i, size - h.dataStart);
                        pos += static_cast<std::size_t>(p.item.size);
                        continue;
                    }
                    if (static_cast<std::size_t>(p.count.size) > size - pos) truncatedBinary(e, i, size - h.dataStart);
                    const std::int64_t length = readInteger(pos, p.count, little);
                    pos += static_cast<std::size_t>(p.count.size);
                    if (length < 0) fail(0, "binary PLY: element '" + e.name + "' #" + std::to_string(i) + " has a list of negative length");
                    if (static_cast<std::uint64_t>(length) * static_cast<std::uint64_t>(p.item.size) > size - pos)
                        truncatedBinary(e, i, size - h.dataStart);
                    pos += static_cast<std::size_t>(length) * static_cast<std::size_t>(p.item.size);
                }
        }
    }

    [[noreturn]] void truncatedBinary(const PlyElement& e, std::uint64_t instance, std::size_t held) const {
        fail(0, "truncated binary PLY: the header announces " + std::to_string(e.count) + " '" + e.name +
                    "' elements; the data ends " + (instance > 0 ? "at #" + std::to_string(instance) : "before them") +
                    " (" + std::to_string(held) + " bytes of data)");
    }

    std::int64_t readInteger(std::size_t pos, const PlyType& t, bool little) const {
        std::uint64_t v = 0;
        for (int b = 0; b < t.size; ++b) {
            const auto byte = static_cast<std::uint8_t>(data_[pos + static_cast<std::size_t>(little ? b : t.size - 1 - b)]);
            v |= static_cast<std::uint64_t>(byte) << (8 * b);
        }
        if (t.isSigned && t.size < 8 && (v >> (8 * t.size - 1)) != 0) return static_cast<std::int64_t>(v) - (std::int64_t{1} << (8 * t.size));
        return static_cast<std::int64_t>(v);
    }

    // ASCII: one instance per line (blank lines skipped), each with exactly the numbers its
    // properties take.
    void asciiData(const PlyHeader& h) const {
        std::size_t pos = h.dataStart;
        int number = h.dataLine - 1;
        std::string_view line;
        for (const PlyElement& e : h.elements)
            for (std::uint64_t i = 0; i < e.count; ++i) {
                std::vector<std::string_view> w;
                do {
                    if (!nextLine(pos, line))
                        fail(number, "truncated ASCII PLY: the header announces " + std::to_string(e.count) + " '" + e.name +
                                         "' elements; the file ends after " + std::to_string(i));
                    ++number;
                    w = words(line);
                } while (w.empty());
                instance(e, w, number);
            }
    }

    void instance(const PlyElement& e, const std::vector<std::string_view>& w, int number) const {
        std::size_t next = 0;
        for (const PlyProperty& p : e.properties) {
            std::uint64_t items = 1;
            if (p.list) {
                if (next >= w.size() || !parseWhole(w[next], items))
                    fail(number, "element '" + e.name + "': a list length must be a non-negative integer");
                ++next;
            }
            if (items > w.size() - next) fail(number, "element '" + e.name + "' has fewer values than its properties take");
            for (std::uint64_t k = 0; k < items; ++k, ++next) {
                double value = 0;
                if (!parseWhole(w[next], value) || !std::isfinite(value))
                    fail(number, "element '" + e.name + "': '" + std::string(w[next]) + "' is not a finite number");
            }
        }
        if (next != w.size()) fail(number, "element '" + e.name + "' has more values than its properties take");
    }

    fs::path file_;
    const std::string& data_;  // the whole file
};

// ---- glTF ----

using nlohmann::json;

std::string percentDecoded(const std::string& uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        unsigned value = 0;
        if (uri[i] == '%' && i + 2 < uri.size() && std::from_chars(uri.data() + i + 1, uri.data() + i + 3, value, 16).ptr == uri.data() + i + 3) {
            out += static_cast<char>(value);
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

class GltfChecker {
public:
    GltfChecker(const fs::path& file, const std::string& data) : file_(file), data_(data) {}

    void check() {
        const bool glb = data_.size() >= 4 && data_.compare(0, 4, "glTF") == 0;
        if (!glb && util::lowerExtension(file_) == ".glb") fail("not a GLB file: it does not start with 'glTF'");
        const std::string text = glb ? container() : data_;
        json root;
        try {
            root = json::parse(text);
        } catch (const json::exception& e) {  // parse_error, or out_of_range for numbers such as 1e309
            const auto* parse = dynamic_cast<const json::parse_error*>(&e);
            const auto upTo = std::min<std::size_t>(parse ? parse->byte : 0, text.size());
            const int line = glb || !parse ? 0 : 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(upTo), '\n'));
            throw InputError(file_, line, std::string(glb ? "the GLB's JSON chunk" : "glTF") + " is not valid JSON: " + e.what());
        }
        if (!root.is_object()) fail("the glTF JSON must be an object");
        buffers(root);
        bufferViews(root);
        accessors(root);
    }

private:
    [[noreturn]] void fail(const std::string& what) const { throw InputError(file_, what); }

    std::uint32_t word(std::size_t at) const {
        std::uint32_t v = 0;
        for (int b = 0; b < 4; ++b) v |= static_cast<std::uint32_t>(static_cast<std::uint8_t>(data_[at + static_cast<std::size_t>(b)])) << (8 * b);
        return v;
    }

    // The GLB container (glTF 2.0 §4.4): a 12-byte header, a JSON chunk, an optional BIN chunk.
    std::string container() {
        if (data_.size() < 20) fail("truncated GLB: " + std::to_string(data_.size()) + " bytes, less than a header and a chunk");
        if (word(4) != 2) fail("GLB version " + std::to_string(word(4)) + "; only version 2 is read");
        const std::uint64_t length = word(8);
        if (length > data_.size()) fail("truncated GLB: the header announces " + std::to_string(length) + " bytes, the file holds " + std::to_string(data_.size()));
        const std::uint64_t jsonLength = word(12);
        if (word(16) != 0x4E4F534Au) fail("the GLB's first chunk must be JSON");
        if (20 + jsonLength > length) fail("truncated GLB: the JSON chunk announces " + std::to_string(jsonLength) + " bytes past the file's end");
        std::size_t at = 20 + static_cast<std::size_t>(jsonLength);
        if (at + 8 <= length && word(at + 4) == 0x004E4942u) {
            binLength_ = word(at);
            if (at + 8 + binLength_ > length) fail("truncated GLB: the BIN chunk announces " + std::to_string(binLength_) + " bytes past the file's end");
            hasBin_ = true;
        }
        return data_.substr(20, static_cast<std::size_t>(jsonLength));
    }

    // nlohmann keeps every non-negative integer it parses as unsigned.
    static bool count(const json& v, std::uint64_t& out) {
        if (!v.is_number_unsigned()) return false;
        out = v.get<std::uint64_t>();
        return true;
    }

    // An optional non-negative integer member of `obj` (fallback when absent).
    std::uint64_t member(const json& obj, const char* key, const std::string& where, std::uint64_t fallback, bool required = false) const {
        if (!obj.contains(key)) {
            if (required) fail(where + "." + key + " is missing");
            return fallback;
        }
        std::uint64_t v = 0;
        if (!count(obj.at(key), v)) fail(where + "." + key + " must be a non-negative integer");
        return v;
    }

    const json& array(const json& root, const char* key) const {
        static const json empty = json::array();
        if (!root.contains(key)) return empty;
        if (!root.at(key).is_array()) fail(std::string(key) + " must be an array");
        return root.at(key);
    }

    // each(item, index, where) for every entry of root[key], which must be an array of objects.
    template <typename Each>
    void forEachObject(const json& root, const char* key, Each each) const {
        const json& list = array(root, key);
        for (std::size_t i = 0; i < list.size(); ++i) {
            const std::string where = std::string(key) + "[" + std::to_string(i) + "]";
            if (!list[i].is_object()) fail(where + " must be an object");
            each(list[i], i, where);
        }
    }

    void buffers(const json& root) {
        forEachObject(root, "buffers", [&](const json& item, std::size_t i, const std::string& where) {
            const std::uint64_t length = member(item, "byteLength", where, 0, true);
            bufferLengths_.push_back(length);
            const std::uint64_t held = bufferBytes(item, i, where);
            if (length > held)
                fail(where + " declares " + std::to_string(length) + " bytes; its data holds " + std::to_string(held));
        });
    }

    // The bytes a buffer's data holds: the BIN chunk, a data: URI, or a file beside the model.
    std::uint64_t bufferBytes(const json& buffer, std::size_t index, const std::string& where) const {
        if (!buffer.contains("uri")) {
            if (index == 0 && hasBin_) return binLength_;
            fail(where + " has no uri and no GLB BIN chunk holds it");
        }
        if (!buffer.at("uri").is_string()) fail(where + ".uri must be a string");
        const std::string uri = buffer.at("uri").get<std::string>();
        if (uri.rfind("data:", 0) == 0) {
            const auto comma = uri.find(',');
            if (comma == std::string::npos || uri.rfind(";base64", comma) == std::string::npos)
                fail(where + ".uri is a data: URI without base64 data");
            const std::size_t chars = uri.size() - comma - 1;
            return chars / 4 * 3;  // an upper bound: padding only lowers it
        }
        std::error_code ec;
        auto size = fs::file_size(file_.parent_path() / uri, ec);
        if (ec) size = fs::file_size(file_.parent_path() / percentDecoded(uri), ec);  // URIs may escape spaces and the like
        if (ec) fail(where + ".uri names '" + uri + "', which cannot be read");
        return size;
    }

    void bufferViews(const json& root) {
        forEachObject(root, "bufferViews", [&](const json& item, std::size_t, const std::string& where) {
            const std::uint64_t buffer = member(item, "buffer", where, 0, true);
            if (buffer >= bufferLengths_.size()) fail(where + ".buffer names buffer " + std::to_string(buffer) + ", which does not exist");
            const std::uint64_t offset = member(item, "byteOffset", where, 0), length = member(item, "byteLength", where, 0, true);
            const std::uint64_t stride = member(item, "byteStride", where, 0);
            if (stride != 0 && (stride < 4 || stride > 252)) fail(where + ".byteStride must be within 4..252");
            if (offset > bufferLengths_[buffer] || length > bufferLengths_[buffer] - offset)
                fail(where + " reaches byte " + std::to_string(offset + length) + " of buffer " + std::to_string(buffer) + ", which has " +
                     std::to_string(bufferLengths_[buffer]));
            views_.push_back({length, stride});
        });
    }

    void accessors(const json& root) const {
        static const std::map<std::uint64_t, std::uint64_t> componentBytes = {{5120, 1}, {5121, 1}, {5122, 2}, {5123, 2}, {5125, 4}, {5126, 4}};
        static const std::map<std::string, std::uint64_t> components = {{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
                                                                          {"MAT2", 4},   {"MAT3", 9}, {"MAT4", 16}};
        forEachObject(root, "accessors", [&](const json& item, std::size_t, const std::string& where) {
            const auto bytes = componentBytes.find(member(item, "componentType", where, 0, true));
            if (bytes == componentBytes.end()) fail(where + ".componentType is not a glTF component type");
            const json& type = item.contains("type") ? item.at("type") : json();
            const auto n = type.is_string() ? components.find(type.get<std::string>()) : components.end();
            if (n == components.end()) fail(where + ".type must be one of SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3, MAT4");
            const std::uint64_t count = member(item, "count", where, 0, true);
            if (count == 0) fail(where + ".count must be at least 1");
            const std::uint64_t element = bytes->second * n->second;
            if (!item.contains("bufferView")) {  // zeros (or sparse values): the importer allocates count elements
                if (count > (std::uint64_t{1} << 28) / element) fail(where + " declares " + std::to_string(count) + " elements with no data");
                return;
            }
            const std::uint64_t view = member(item, "bufferView", where, 0);
            if (view >= views_.size()) fail(where + ".bufferView names view " + std::to_string(view) + ", which does not exist");
            const std::uint64_t offset = member(item, "byteOffset", where, 0);
            const std::uint64_t stride = views_[view].stride != 0 ? views_[view].stride : element;
            const std::uint64_t available = views_[view].length;
            // offset + stride * (count - 1) + element <= available, without overflow
            if (offset > available || element > available - offset || (count - 1) > (available - offset - element) / stride)
                fail(where + ": " + std::to_string(count) + " elements of " + std::to_string(element) + " bytes do not fit bufferView " +
                     std::to_string(view) + " (" + std::to_string(available) + " bytes)");
        });
    }

    struct View {
        std::uint64_t length, stride;
    };
    fs::path file_;
    const std::string& data_;  // the whole file
    bool hasBin_ = false;
    std::uint64_t binLength_ = 0;
    std::vector<std::uint64_t> bufferLengths_;
    std::vector<View> views_;
};

}  // namespace

void checkPly(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    const bool looksPly = in.gcount() >= 4 && std::memcmp(magic, "ply", 3) == 0 && (magic[3] == '\n' || magic[3] == '\r');
    if (!looksPly && util::lowerExtension(file) != ".ply") return;
    const std::string data = util::readBytes(file);
    PlyChecker(file, data).check();
}

void checkGltf(const fs::path& file) {
    const std::string e = util::lowerExtension(file);
    if (e != ".gltf" && e != ".glb") return;
    const std::string data = util::readBytes(file);
    GltfChecker(file, data).check();
}

}  // namespace penumbra::scene::io
