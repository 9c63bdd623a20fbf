#include "bodies/TriSurface.H"

#include "dictionary/Dictionary.H"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <boost/function_output_iterator.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace gpic {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh>>>;

std::string pointText(const TriSurface::Vector& p)
{
    std::ostringstream out;
    out << "(" << p.x() << " " << p.y() << " " << p.z() << ")";
    return out.str();
}

//- CGAL's mesh of the corners and facets, face k being facet k.
void buildMesh(const std::vector<TriSurface::Vector>& corners, const std::vector<TriSurface::Facet>& facets,
               Mesh& mesh)
{
    std::vector<Point> points;
    points.reserve(corners.size());
    for (const TriSurface::Vector& c : corners) points.emplace_back(c.x(), c.y(), c.z());
    std::vector<std::array<std::size_t, 3>> soup;
    soup.reserve(facets.size());
    for (const TriSurface::Facet& t : facets) soup.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, soup, mesh);
}

//- The solids of an ASCII STL file in order, with their names and facet counts; empty for a
//  binary file (whose 80-byte header may begin with "solid" too: the caller compares counts).
std::vector<std::pair<std::string, std::size_t>> asciiSolids(const std::string& path)
{
    std::ifstream in(path);
    std::vector<std::pair<std::string, std::size_t>> solids;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string word;
        if (!(words >> word)) continue;
        if (word == "solid") {
            std::string name;
            words >> name;
            solids.emplace_back(name, 0);
        } else if (word == "facet" && !solids.empty()) {
            ++solids.back().second;
        } else if (solids.empty()) {
            return {};  // not an ASCII STL
        }
    }
    return solids;
}

} // namespace

struct TriSurface::Search {
    Mesh mesh;
    std::unique_ptr<CGAL::Side_of_triangle_mesh<Mesh, Kernel>> side;
    std::unique_ptr<Tree> tree;  //- the facets, for nearest points
    std::vector<Vector> normals;  //- unit, outward, by facet
};

TriSurface::TriSurface(std::vector<Vector> corners, std::vector<Facet> facets, std::string name)
    : corners_(std::move(corners)), facets_(std::move(facets)), name_(std::move(name))
{}

TriSurface TriSurface::box(const Vector& lo, const Vector& hi, std::string name)
{
    std::vector<Vector> corners;
    for (int k = 0; k < 8; ++k)  // corner k: bit 0 x, bit 1 y, bit 2 z at the high end
        corners.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
    std::vector<Facet> facets = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    return TriSurface(std::move(corners), std::move(facets), std::move(name));
}

TriSurface TriSurface::read(const Dictionary& dict)
{
    const std::string path = dict.filePath("file");
    const std::string shown = dict.get<std::string>("file");
    if (!std::filesystem::is_regular_file(path))
        dict.fail("file", "cannot open surface file \"" + shown + "\" (looked for " + path + ")");
    std::vector<Point> points;
    std::vector<std::array<std::size_t, 3>> soup;
    if (!CGAL::IO::read_STL(path, points, soup))
        dict.fail("file", "\"" + shown + "\" is not an STL file (ASCII or binary) that can be read");
    if (soup.empty()) dict.fail("file", "\"" + shown + "\" holds no facet");

    const double scale = dict.getOrDefault<double>("scale", 1.0);
    if (!(scale > 0)) dict.fail("scale", "scale must be > 0 (the file's unit in metres)");
    Eigen::Matrix3d turn = Eigen::Matrix3d::Identity();
    if (const Dictionary* rotation = dict.subDictPtr("rotation")) {
        const Vector axis = rotation->get<Vector>("axis");
        if (!(axis.norm() > 0)) rotation->fail("axis", "the rotation axis must not be zero");
        const double angle = rotation->get<double>("angle") * M_PI / 180.0;
        turn = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
        rotation->warnUnused();
    }
    const Vector shift = dict.getOrDefault<Vector>("translation", Vector::Zero());

    std::vector<Vector> corners;
    corners.reserve(points.size());
    for (const Point& p : points) corners.push_back(turn * (scale * Vector(p.x(), p.y(), p.z())) + shift);
    std::vector<Facet> facets;
    facets.reserve(soup.size());
    for (const auto& f : soup)
        facets.push_back({static_cast<int>(f[0]), static_cast<int>(f[1]), static_cast<int>(f[2])});
    TriSurface surface(std::move(corners), std::move(facets), shown);
    if (const std::string why = surface.fault(); !why.empty()) dict.fail("file", "surface \"" + shown + "\" " + why);
    // Parts: the ASCII file's solids, facets in the order CGAL read them (the file's).
    const auto solids = asciiSolids(path);
    std::size_t counted = 0;
    for (const auto& solid : solids) counted += solid.second;
    if (!solids.empty() && counted == surface.facets_.size()) {
        surface.partNames_.clear();
        surface.partOfFacet_.reserve(counted);
        for (std::size_t k = 0; k < solids.size(); ++k) {
            const std::string name = solids[k].first.empty() ? "part" + std::to_string(k + 1) : solids[k].first;
            const auto known = std::find(surface.partNames_.begin(), surface.partNames_.end(), name);
            const int part = static_cast<int>(known - surface.partNames_.begin());
            if (known == surface.partNames_.end()) surface.partNames_.push_back(name);
            surface.partOfFacet_.insert(surface.partOfFacet_.end(), solids[k].second, part);
        }
        if (surface.partNames_.size() == 1) surface.partOfFacet_.clear();
    }
    return surface;
}

std::string TriSurface::fault() const
{
    if (facets_.empty()) return "holds no facet";
    const auto edgeText = [&](int a, int b) { return pointText(corners_[a]) + " - " + pointText(corners_[b]); };
    for (std::size_t f = 0; f < facets_.size(); ++f) {
        const Facet& t = facets_[f];
        const Vector n = (corners_[t[1]] - corners_[t[0]]).cross(corners_[t[2]] - corners_[t[0]]);
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] || !(n.norm() > 0))
            return "has a degenerate facet (number " + std::to_string(f + 1) + ", corners " +
                   pointText(corners_[t[0]]) + " " + pointText(corners_[t[1]]) + " " +
                   pointText(corners_[t[2]]) + "): it has no area";
    }
    // Each edge, by its lower corner index first: the facets that use it, and along which way.
    struct Use {
        std::size_t facet;
        bool forward;
    };
    std::map<std::pair<int, int>, std::vector<Use>> edges;
    for (std::size_t f = 0; f < facets_.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int a = facets_[f][k], b = facets_[f][(k + 1) % 3];
            edges[{std::min(a, b), std::max(a, b)}].push_back({f, a < b});
        }
    for (const auto& [edge, uses] : edges) {
        if (uses.size() == 1)
            return "is not closed: its edge " + edgeText(edge.first, edge.second) +
                   " belongs to one facet only (number " + std::to_string(uses[0].facet + 1) +
                   "); a solid needs a watertight surface";
        if (uses.size() > 2)
            return "is not manifold: its edge " + edgeText(edge.first, edge.second) + " is shared by " +
                   std::to_string(uses.size()) + " facets; a solid's edge joins exactly two";
        if (uses[0].forward == uses[1].forward)
            return "is not oriented consistently: facets " + std::to_string(uses[0].facet + 1) + " and " +
                   std::to_string(uses[1].facet + 1) + " run the same way along their edge " +
                   edgeText(edge.first, edge.second) + ", so one of them faces inward";
    }
    const double v = volume();
    if (!(v > 0)) {
        std::ostringstream out;
        out << "faces inward: the volume it encloses comes out " << v
            << " m^3; turn its facets over (reverse their corner order)";
        return out.str();
    }
    // A surface crossing itself has no one inside: the inside test would depend on the ray.
    Mesh mesh;
    buildMesh(corners_, facets_, mesh);
    std::pair<int, int> crossing{-1, -1};
    CGAL::Polygon_mesh_processing::self_intersections(
        mesh, boost::make_function_output_iterator([&](const std::pair<Mesh::Face_index, Mesh::Face_index>& p) {
            if (crossing.first < 0) crossing = {int(p.first), int(p.second)};
        }));
    if (crossing.first >= 0)
        return "intersects itself: facets " + std::to_string(crossing.first + 1) + " and " +
               std::to_string(crossing.second + 1) + " cross";
    return "";
}

double TriSurface::volume() const
{
    // Each facet with the origin spans a tetrahedron of signed volume a . (b x c) / 6.
    double six = 0.0;
    for (const Facet& t : facets_) six += corners_[t[0]].dot(corners_[t[1]].cross(corners_[t[2]]));
    return six / 6.0;
}

std::pair<TriSurface::Vector, TriSurface::Vector> TriSurface::bounds() const
{
    Vector lo = corners_.front(), hi = corners_.front();
    for (const Vector& c : corners_) {
        lo = lo.cwiseMin(c);
        hi = hi.cwiseMax(c);
    }
    return {lo, hi};
}

const TriSurface::Search& TriSurface::search() const
{
    if (!search_) {
        auto search = std::make_shared<Search>();
        buildMesh(corners_, facets_, search->mesh);
        search->side = std::make_unique<CGAL::Side_of_triangle_mesh<Mesh, Kernel>>(search->mesh);
        search->tree = std::make_unique<Tree>(faces(search->mesh).first, faces(search->mesh).second, search->mesh);
        search->tree->accelerate_distance_queries();
        for (const Facet& t : facets_)
            search->normals.push_back(
                (corners_[t[1]] - corners_[t[0]]).cross(corners_[t[2]] - corners_[t[0]]).normalized());
        search_ = std::move(search);
    }
    return *search_;
}

bool TriSurface::inside(const Vector& x) const
{
    return (*search().side)(Point(x.x(), x.y(), x.z())) != CGAL::ON_UNBOUNDED_SIDE;
}

TriSurface::Vector TriSurface::facetNormal(int f) const { return search().normals[static_cast<std::size_t>(f)]; }

TriSurface::FacetPoint TriSurface::nearest(const Vector& x) const
{
    const auto [foot, face] = search().tree->closest_point_and_primitive(Point(x.x(), x.y(), x.z()));
    const Vector f(foot.x(), foot.y(), foot.z());
    return {static_cast<int>(face), f, (x - f).norm()};
}

std::vector<TriSurface::FacetPoint> TriSurface::facetsNear(const Vector& x, double reach) const
{
    const Search& s = search();
    std::vector<Tree::Primitive_id> hits;
    const Kernel::Iso_cuboid_3 box(Point(x.x() - reach, x.y() - reach, x.z() - reach),
                                   Point(x.x() + reach, x.y() + reach, x.z() + reach));
    s.tree->all_intersected_primitives(box, std::back_inserter(hits));
    std::vector<FacetPoint> near;
    const Point p(x.x(), x.y(), x.z());
    for (const auto face : hits) {
        const Facet& t = facets_[static_cast<std::size_t>(face)];
        const auto corner = [&](int k) { return Point(corners_[t[k]].x(), corners_[t[k]].y(), corners_[t[k]].z()); };
        const Point foot = Kernel::Construct_projected_point_3()(Kernel::Triangle_3(corner(0), corner(1), corner(2)), p);
        const Vector f(foot.x(), foot.y(), foot.z());
        if ((x - f).norm() <= reach) near.push_back({static_cast<int>(face), f, (x - f).norm()});
    }
    return near;
}

int TriSurface::facetPushedBy(const Vector& x, const Vector& push, double band, double reach,
                              double* nearestDistance) const
{
    const FacetPoint near = nearest(x);
    if (nearestDistance) *nearestDistance = near.distance;
    if (near.distance > reach) return -1;
    int facet = near.facet;
    double against = -push.dot(facetNormal(facet));
    for (const FacetPoint& other : facetsNear(x, near.distance + band)) {
        const double a = -push.dot(facetNormal(other.facet));
        if (a > against) {
            against = a;
            facet = other.facet;
        }
    }
    return facet;
}

double TriSurface::facetArea(int f) const
{
    const Facet& t = facets_[static_cast<std::size_t>(f)];
    return 0.5 * (corners_[t[1]] - corners_[t[0]]).cross(corners_[t[2]] - corners_[t[0]]).norm();
}

} // namespace gpic
