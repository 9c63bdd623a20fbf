#include "parallel/CellDecompositionFile.H"

#include "core/error.H"
#include "dictionary/Dictionary.H"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace gpic {

void writeCellDecomposition(const std::string& path, const CellDecomposition& d)
{
    std::ostringstream os;
    os << fileHeader("cellDecomposition", "constant")
       << "// The subdomain of each cell, numbered i + nx (j + ny k) as the grid numbers them.\n"
       << "numberOfSubdomains " << d.subdomains << ";\nnCells " << d.owner.size() << ";\nowner\n(";
    for (std::size_t c = 0; c < d.owner.size(); ++c) os << (c % 32 == 0 ? "\n" : " ") << d.owner[c];
    os << "\n);\n";
    // Written apart and renamed: a run stopped while writing leaves the old owners whole.
    const std::string tmp = path + ".tmp";
    std::ofstream out(tmp);
    out << os.str();
    out.close();
    if (!out || std::rename(tmp.c_str(), path.c_str()) != 0)
        throw RunError("cannot write the cell decomposition to " + path);
}

CellDecomposition readCellDecomposition(const std::string& path, int nCells)
{
    const Dictionary dict = Dictionary::readFile(path);
    CellDecomposition d;
    d.subdomains = dict.getChecked<int>("numberOfSubdomains", [](int n) { return n >= 1; }, "numberOfSubdomains >= 1");
    dict.getChecked<int>("nCells", [nCells](int n) { return n == nCells; },
                         "nCells = " + std::to_string(nCells) + ", the cells of constant/grid");
    d.owner = dict.get<std::vector<int>>("owner");
    if (static_cast<int>(d.owner.size()) != nCells)
        dict.fail("owner", "expected " + std::to_string(nCells) + " owners, one per cell, got " +
                               std::to_string(d.owner.size()));
    for (int o : d.owner)
        if (o < 0 || o >= d.subdomains)
            dict.fail("owner", "owner " + std::to_string(o) + " outside 0 ... " + std::to_string(d.subdomains - 1));
    return d;
}

} // namespace gpic
