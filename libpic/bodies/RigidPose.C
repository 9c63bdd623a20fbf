#include "bodies/RigidPose.H"

#include "particles/Particles.H"

#include <Eigen/LU>
#include <Eigen/SVD>

namespace gpic {

#if GPIC_WITH_3D
RigidPose RigidPose::of(const Particles<3>& particles, int body, const RankReductions& ranks)
{
    RigidPose pose;
    double mass = 0;
    for (std::size_t q = 0; q < particles.size(); ++q)
        if (particles.body[q] == body) {
            pose.c0 += particles.m[q] * particles.x0[q];
            pose.c += particles.m[q] * particles.x[q];
            mass += particles.m[q];
        }
    if (ranks.parallel()) {
        std::vector<double> sums{mass};
        sums.insert(sums.end(), pose.c0.data(), pose.c0.data() + 3);
        sums.insert(sums.end(), pose.c.data(), pose.c.data() + 3);
        ranks.sumOver(sums);
        mass = sums[0];
        for (int a = 0; a < 3; ++a) pose.c0[a] = sums[1 + a], pose.c[a] = sums[4 + a];
    }
    if (!(mass > 0)) return RigidPose{};
    pose.c0 /= mass;
    pose.c /= mass;
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    for (std::size_t q = 0; q < particles.size(); ++q)
        if (particles.body[q] == body)
            H.noalias() += particles.m[q] * (particles.x0[q] - pose.c0) * (particles.x[q] - pose.c).transpose();
    if (ranks.parallel()) {
        std::vector<double> sums(H.data(), H.data() + 9);
        ranks.sumOver(sums);
        H = Eigen::Map<const Eigen::Matrix3d>(sums.data());
    }
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Matrix3d turn = svd.matrixV() * svd.matrixU().transpose();
    Eigen::Matrix3d flip = Eigen::Matrix3d::Identity();
    flip(2, 2) = turn.determinant() < 0 ? -1.0 : 1.0;  // a turn, not a mirror
    pose.R = svd.matrixV() * flip * svd.matrixU().transpose();
    return pose;
}
#endif

} // namespace gpic
