#include "io/PvdCollection.H"

#include "core/error.H"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>

namespace gpic {

namespace {

bool sameTime(double a, double b)
{
    return std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b));
}

std::string escapeXml(const std::string& s)
{
    std::string out;
    for (char c : s) {
        switch (c) {
        case '&': out += "&amp;"; break;
        case '<': out += "&lt;"; break;
        case '>': out += "&gt;"; break;
        case '"': out += "&quot;"; break;
        default: out += c;
        }
    }
    return out;
}

std::string unescapeXml(const std::string& s)
{
    static const std::pair<const char*, char> entities[] = {
        {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
    std::string out;
    for (std::size_t i = 0; i < s.size();) {
        bool replaced = false;
        if (s[i] == '&')
            for (const auto& [text, c] : entities)
                if (s.compare(i, std::char_traits<char>::length(text), text) == 0) {
                    out += c;
                    i += std::char_traits<char>::length(text);
                    replaced = true;
                    break;
                }
        if (!replaced) out += s[i++];
    }
    return out;
}

//- Attributes name="value" (or 'value') of one element's text.
std::map<std::string, std::string> attributes(const std::string& element)
{
    std::map<std::string, std::string> result;
    std::size_t i = 0;
    while ((i = element.find('=', i)) != std::string::npos) {
        std::size_t nameEnd = i;
        while (nameEnd > 0 && std::isspace(static_cast<unsigned char>(element[nameEnd - 1])))
            --nameEnd;
        std::size_t nameBegin = nameEnd;
        while (nameBegin > 0 && !std::isspace(static_cast<unsigned char>(element[nameBegin - 1])) &&
               element[nameBegin - 1] != '"' && element[nameBegin - 1] != '\'')
            --nameBegin;
        std::size_t q = i + 1;
        while (q < element.size() && std::isspace(static_cast<unsigned char>(element[q]))) ++q;
        if (q >= element.size() || (element[q] != '"' && element[q] != '\'')) { ++i; continue; }
        const std::size_t close = element.find(element[q], q + 1);
        if (close == std::string::npos) break;
        result[element.substr(nameBegin, nameEnd - nameBegin)] =
            unescapeXml(element.substr(q + 1, close - q - 1));
        i = close + 1;
    }
    return result;
}

} // namespace

PvdCollection::PvdCollection(std::string path) : path_(std::move(path))
{
    std::error_code ec;
    if (std::filesystem::exists(path_, ec)) load();
}

void PvdCollection::load()
{
    std::ifstream in(path_, std::ios::binary);
    if (!in) throw InputError(path_, 0, "cannot open the ParaView collection file");
    std::stringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();

    // Scan for DataSet elements rather than parse XML: the file is ours, but a user may have
    // edited it, and a broken entry should cost that entry only.
    int line = 1;
    std::size_t counted = 0;  // line numbers are counted incrementally: files can be long
    for (std::size_t pos = text.find("<DataSet"); pos != std::string::npos;
         pos = text.find("<DataSet", pos + 1)) {
        line += static_cast<int>(std::count(text.begin() + counted, text.begin() + pos, '\n'));
        counted = pos;
        const std::size_t end = text.find('>', pos);
        if (end == std::string::npos) {
            warning(path_, line, "unterminated DataSet element ignored");
            break;
        }
        auto attrs = attributes(text.substr(pos + 8, end - pos - 8));
        const std::string& t = attrs["timestep"];
        char* tEnd = nullptr;
        const double time = std::strtod(t.c_str(), &tEnd);
        if (t.empty() || *tEnd != '\0' || !std::isfinite(time) || attrs["file"].empty()) {
            warning(path_, line, "DataSet without a valid timestep and file ignored");
            continue;
        }
        int part = 0;
        if (!attrs["part"].empty()) part = std::atoi(attrs["part"].c_str());
        add(time, attrs["file"], part);
    }
}

void PvdCollection::add(double time, const std::string& relativeFile, int part)
{
    // ParaView groups parts by the exact timestep value: reuse the one already listed.
    for (const auto& e : entries_)
        if (sameTime(e.time, time)) {
            time = e.time;
            break;
        }
    for (auto& e : entries_)
        if (e.part == part && e.time == time) {
            e.file = relativeFile;
            return;
        }
    const PvdEntry entry{time, part, relativeFile};
    const auto at = std::upper_bound(
        entries_.begin(), entries_.end(), entry, [](const PvdEntry& a, const PvdEntry& b) {
            return a.time < b.time || (a.time == b.time && a.part < b.part);
        });
    entries_.insert(at, entry);
}

void PvdCollection::removeAfter(double time)
{
    const auto later = [&](const PvdEntry& e) { return e.time > time && !sameTime(e.time, time); };
    entries_.erase(std::remove_if(entries_.begin(), entries_.end(), later), entries_.end());
}

void PvdCollection::removeTime(double time)
{
    entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
                                  [&](const PvdEntry& e) { return sameTime(e.time, time); }),
                   entries_.end());
}

void PvdCollection::write() const
{
    std::ostringstream out;
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <Collection>\n";
    for (const auto& e : entries_) {
        char time[64];
        std::snprintf(time, sizeof time, "%.17g", e.time);
        out << "    <DataSet timestep=\"" << time << "\" group=\"\" part=\"" << e.part
            << "\" file=\"" << escapeXml(e.file) << "\"/>\n";
    }
    out << "  </Collection>\n</VTKFile>\n";

    const std::string tmp = path_ + ".tmp";
    {
        std::ofstream file(tmp, std::ios::binary | std::ios::trunc);
        file << out.str();
        file.close();
        if (!file) {
            std::error_code ignore;
            std::filesystem::remove(tmp, ignore);
            throw RunError("cannot write ParaView collection " + path_);
        }
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path_, ec);
    if (ec) {
        std::error_code ignore;
        std::filesystem::remove(tmp, ignore);
        throw RunError("cannot write ParaView collection " + path_ + ": " + ec.message());
    }
}

} // namespace gpic
