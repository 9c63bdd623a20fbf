#include "io/ParticlesVtkCheck.H"

#include "io/ParticlesVtkFormat.H"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <utility>

namespace gpic {
namespace detail {

namespace {

//- The value of attribute `name` in one XML element's text ("" when absent).
std::string attribute(const std::string& element, const std::string& name)
{
    const std::string key = " " + name + "=\"";
    const auto at = element.find(key);
    if (at == std::string::npos) return "";
    const auto begin = at + key.size();
    const auto close = element.find('"', begin);
    return element.substr(begin, close == std::string::npos ? std::string::npos : close - begin);
}

//- A whole-string unsigned decimal count.
bool parseCount(const std::string& text, std::uint64_t& value)
{
    if (text.empty() || !std::isdigit(static_cast<unsigned char>(text.front()))) return false;
    char* tail = nullptr;
    errno = 0;
    value = std::strtoull(text.c_str(), &tail, 10);
    return *tail == '\0' && errno == 0;
}

} // namespace

ParticlesFileLayout checkParticlesLayout(const std::string& path)
{
    // Known types and their sizes (0: not checked by size).
    static const std::array<std::pair<const char*, std::uint64_t>, 11> known{{
        {"Int8", 1}, {"UInt8", 1}, {"Int16", 2}, {"UInt16", 2}, {"Int32", 4}, {"UInt32", 4},
        {"Int64", 8}, {"UInt64", 8}, {"Float32", 4}, {"Float64", 8}, {"String", 0}}};
    std::ifstream in(path, std::ios::binary);
    in.seekg(0, std::ios::end);
    const auto fileSize = static_cast<std::uint64_t>(in.tellg());
    in.seekg(0);

    // The XML part ends at the '_' that opens the appended binary block.
    std::string header;
    std::size_t tag = std::string::npos, underscore = std::string::npos;
    char chunk[4096];
    while (underscore == std::string::npos && in.read(chunk, sizeof chunk).gcount() > 0) {
        header.append(chunk, static_cast<std::size_t>(in.gcount()));
        if (tag == std::string::npos) tag = header.find("<AppendedData");
        if (tag != std::string::npos) underscore = header.find('_', tag);
    }
    const auto file = header.find("<VTKFile");
    const std::string root =
        file == std::string::npos ? "" : header.substr(file, header.find('>', file) - file);
    if (attribute(root, "type") != "PolyData") cannotReadParticles(path, "not a VTK XML PolyData file");
    if (underscore == std::string::npos) cannotReadParticles(path, "no appended data block");
    // VTK takes the first non-blank character after the tag as the start of the data.
    const auto tagEnd = header.find('>', tag);
    if (tagEnd > underscore || header.find_first_not_of(" \t\r\n", tagEnd + 1) != underscore)
        cannotReadParticles(path, "corrupt appended data block");
    in.clear();
    const std::uint64_t dataStart = underscore + 1;
    const std::string appendedElement = header.substr(tag, tagEnd - tag);
    header.resize(tag);

    if (attribute(root, "header_type") != "UInt64" ||
        root.find(" compressor=") != std::string::npos)
        cannotReadParticles(path, "not written by writeParticles (expected "
                                  "header_type=\"UInt64\" and no compressor)");
    if (attribute(root, "byte_order") != "LittleEndian" || attribute(appendedElement, "encoding") != "raw")
        cannotReadParticles(path, "not written by writeParticles (expected "
                                  "byte_order=\"LittleEndian\" and raw appended data)");

    // Point arrays have NumberOfPoints tuples; with the byte counts checked against it, a
    // corrupt count cannot make the reader allocate or read more than the file holds.
    const auto piece = header.find("<Piece");
    const std::string pieceElement =
        piece == std::string::npos ? "" : header.substr(piece, header.find('>', piece) - piece);
    std::uint64_t nPoints = 0;
    if (!parseCount(attribute(pieceElement, "NumberOfPoints"), nPoints))
        cannotReadParticles(path, "no NumberOfPoints");
    if (header.find("<Piece", piece + 1) != std::string::npos)
        cannotReadParticles(path, "not written by writeParticles (more than one piece)");
    const auto inside = [&](std::size_t pos, const char* open, const char* close) {
        const auto o = header.rfind(open, pos);
        const auto c = header.rfind(close, pos);
        return o != std::string::npos && (c == std::string::npos || c < o);
    };

    // Both kinds of element, in file order.
    std::vector<std::size_t> elements;
    for (const char* name : {"<DataArray", "<Array"})
        for (auto pos = header.find(name); pos != std::string::npos; pos = header.find(name, pos + 1))
            elements.push_back(pos);
    std::sort(elements.begin(), elements.end());

    ParticlesFileLayout layout;
    layout.nPoints = nPoints;
    for (const std::size_t pos : elements) {
        const auto end = header.find('>', pos);
        const std::string element =
            header.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
        const std::string arrayName = attribute(element, "Name");
        const std::string type = attribute(element, "type");
        const auto kind = std::find_if(known.begin(), known.end(),
                                       [&](const auto& k) { return type == k.first; });
        if (kind == known.end()) cannotReadParticles(path, "unknown array type '" + type + "'");
        if (attribute(element, "format") != "appended")
            cannotReadParticles(path, "array '" + arrayName + "' is not appended data");

        // Each block is a UInt64 byte count followed by that many bytes.
        std::uint64_t offset = 0, bytes = 0;
        const bool offsetOk = parseCount(attribute(element, "offset"), offset);
        const std::uint64_t at = dataStart + offset;
        if (!offsetOk || offset > fileSize || at > fileSize || fileSize - at < 8 ||
            !in.seekg(static_cast<std::streamoff>(at)) ||
            !in.read(reinterpret_cast<char*>(&bytes), sizeof bytes) ||
            bytes > fileSize - at - 8)
            cannotReadParticles(path, "truncated or corrupt: data of array '" + arrayName +
                                          "' runs past the end of the file");
        std::uint64_t tuples = 0, components = 1;
        const bool inPointData = inside(pos, "<PointData", "</PointData>");
        const bool inPoints = inside(pos, "<Points>", "</Points>");
        const bool pointArray = inPointData || inPoints;
        const bool counted = pointArray || !attribute(element, "NumberOfTuples").empty();
        if (pointArray) tuples = nPoints;
        else if (counted && !parseCount(attribute(element, "NumberOfTuples"), tuples))
            cannotReadParticles(path, "bad NumberOfTuples of array '" + arrayName + "'");
        if (!attribute(element, "NumberOfComponents").empty() &&
            !parseCount(attribute(element, "NumberOfComponents"), components))
            cannotReadParticles(path, "bad NumberOfComponents of array '" + arrayName + "'");
        bool sizeOk = true;
        if (counted && kind->second > 0) {
            // Divide rather than multiply, so that corrupt counts cannot overflow.
            if (tuples == 0 || components == 0) sizeOk = bytes == 0;
            else if (components > fileSize) sizeOk = false;
            else sizeOk = bytes % (components * kind->second) == 0 &&
                          bytes / (components * kind->second) == tuples;
        }
        if (!sizeOk)
            cannotReadParticles(path, "array '" + arrayName + "' holds " +
                                          std::to_string(bytes) + " bytes, expected " +
                                          std::to_string(tuples) + " tuples of " +
                                          std::to_string(components) + " " + type);
        ParticleFileArray a;
        a.section = inPointData ? ParticleFileArray::Section::point
                    : inPoints  ? ParticleFileArray::Section::points
                    : inside(pos, "<FieldData", "</FieldData>") ? ParticleFileArray::Section::field
                                                                : ParticleFileArray::Section::other;
        a.name = arrayName;
        a.type = type;
        a.components = components;
        a.tuples = tuples;
        a.bytes = bytes;
        a.dataAt = at + 8;
        if (type == "String") {
            // NumberOfTuples strings, each terminated by '\0', filling the block exactly.
            std::string block(bytes, '\0');
            in.read(block.data(), static_cast<std::streamsize>(bytes));
            const auto strings = std::count(block.begin(), block.end(), '\0');
            if (!in || (bytes > 0 && block.back() != '\0') ||
                std::to_string(strings) != attribute(element, "NumberOfTuples"))
                cannotReadParticles(path, "corrupt string array '" + arrayName + "'");
            if (a.section == ParticleFileArray::Section::field)
                for (std::size_t begin = 0; begin < block.size();) {
                    const auto zero = block.find('\0', begin);
                    a.strings.push_back(block.substr(begin, zero - begin));
                    begin = zero + 1;
                }
        }
        layout.arrays.push_back(std::move(a));
    }
    return layout;
}

} // namespace detail
} // namespace gpic
