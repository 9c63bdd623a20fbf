#include "PointHistoryFile.H"

#include "core/error.H"

namespace gpic {

template <int D>
PointHistoryFile<D>::PointHistoryFile(const std::string& path, const MaterialPoint<D>& point)
    : path_(path), out_(path)
{
    if (!out_) throw RunError("cannot write " + path_);
    out_.precision(12);
    if constexpr (D == 2) out_ << "step,eps11,eps22,eps12,sigma11,sigma22,sigma33,sigma12,p,q";
    else
        out_ << "step,eps11,eps22,eps33,eps12,eps23,eps13,sigma11,sigma22,sigma33,sigma12,sigma23,sigma13,p,q";
    for (const auto& name : point.historyNames()) out_ << ',' << name;
    out_ << '\n';
}

template <int D> void PointHistoryFile<D>::write(int step, const MaterialPoint<D>& point)
{
    const auto& e = point.eps();
    const auto& s = point.sigma();
    if constexpr (D == 2)
        out_ << step << ',' << e[XX] << ',' << e[YY] << ',' << e[XY] << ',' << s[XX] << ',' << s[YY] << ',' << s[ZZ]
             << ',' << s[XY] << ',' << point.p() << ',' << point.q();
    else {
        out_ << step;
        for (int k = 0; k < 6; ++k) out_ << ',' << e[k];
        for (int k = 0; k < 6; ++k) out_ << ',' << s[k];
        out_ << ',' << point.p() << ',' << point.q();
    }
    for (double h : point.history()) out_ << ',' << h;
    out_ << '\n';
}

template <int D> void PointHistoryFile<D>::close()
{
    out_.close();
    if (!out_) throw RunError("writing " + path_ + " failed (disk full?)");
}

template class PointHistoryFile<2>;
#if GPIC_WITH_3D
template class PointHistoryFile<3>;
#endif

} // namespace gpic
