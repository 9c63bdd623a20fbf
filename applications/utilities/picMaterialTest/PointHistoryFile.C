#include "PointHistoryFile.H"

#include "core/error.H"

namespace gpic {

PointHistoryFile::PointHistoryFile(const std::string& path, const MaterialPoint& point)
    : path_(path), out_(path)
{
    if (!out_) throw RunError("cannot write " + path_);
    out_.precision(12);
    out_ << "step,eps11,eps22,eps12,sigma11,sigma22,sigma33,sigma12,p,q";
    for (const auto& name : point.historyNames()) out_ << ',' << name;
    out_ << '\n';
}

void PointHistoryFile::write(int step, const MaterialPoint& point)
{
    const SymTensor& e = point.eps();
    const SymTensor& s = point.sigma();
    out_ << step << ',' << e[XX] << ',' << e[YY] << ',' << e[XY] << ',' << s[XX] << ',' << s[YY]
         << ',' << s[ZZ] << ',' << s[XY] << ',' << point.p() << ',' << point.q();
    for (double h : point.history()) out_ << ',' << h;
    out_ << '\n';
}

void PointHistoryFile::close()
{
    out_.close();
    if (!out_) throw RunError("writing " + path_ + " failed (disk full?)");
}

} // namespace gpic
