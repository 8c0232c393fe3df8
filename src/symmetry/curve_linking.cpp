// Stage 1, second half: boundary points linked by a minimum spanning tree, and the tree cut
// into ordered curves, each the longest path left in its part of the tree.
#include <algorithm>
#include <cmath>
#include <tuple>

#include <Eigen/Eigenvalues>
#include <pcl/kdtree/kdtree_flann.h>

#include "disjoint_sets.h"
#include "symmetry_segmentation/symmetry/normal_edge_curves.h"

namespace symmetry_segmentation {
namespace {

struct Edge {
  float length;
  int a, b;  // a < b: ties in length are broken by index, so the tree is deterministic.
  bool operator<(const Edge& other) const {
    return std::tie(length, a, b) < std::tie(other.length, other.a, other.b);
  }
};

using Adjacency = std::vector<std::vector<std::pair<int, float>>>;

/// Kruskal over the links no longer than curve_link_radius between points of one segment
/// (a forest if they do not connect).
Adjacency minimumSpanningForest(const std::vector<Eigen::Vector3f>& positions, const std::vector<int>& segment,
                                float link_radius) {
  auto points = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  points->reserve(positions.size());
  for (const auto& p : positions) points->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(points);

  std::vector<Edge> edges;
  std::vector<int> neighbours;
  std::vector<float> squared_distances;
  for (int i = 0; i < static_cast<int>(positions.size()); ++i) {
    tree.radiusSearch(points->points[i], link_radius, neighbours, squared_distances);
    for (std::size_t k = 0; k < neighbours.size(); ++k) {
      if (neighbours[k] > i && segment[neighbours[k]] == segment[i]) edges.push_back({std::sqrt(squared_distances[k]), i, neighbours[k]});
    }
  }
  std::sort(edges.begin(), edges.end());

  Adjacency tree_edges(positions.size());
  DisjointSets sets(positions.size());
  for (const Edge& e : edges) {
    if (!sets.unite(e.a, e.b)) continue;
    tree_edges[e.a].emplace_back(e.b, e.length);
    tree_edges[e.b].emplace_back(e.a, e.length);
  }
  return tree_edges;
}

/// Distances along the tree from `source` over live vertices; returns the farthest vertex
/// (smallest index on ties) and fills `parent` for walking back.
int farthestVertex(const Adjacency& tree, const std::vector<char>& alive, int source, std::vector<float>& distance,
                   std::vector<int>& parent) {
  std::vector<int> stack{source};
  distance[source] = 0.0f;
  parent[source] = -1;
  int farthest = source;
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    if (distance[v] > distance[farthest] || (distance[v] == distance[farthest] && v < farthest)) farthest = v;
    for (const auto& [w, length] : tree[v]) {
      if (!alive[w] || w == parent[v]) continue;
      parent[w] = v;
      distance[w] = distance[v] + length;
      stack.push_back(w);
    }
  }
  return farthest;
}

/// Principal direction of the curve points within +-half_window along the curve.
std::vector<Eigen::Vector3f> curveTangents(const std::vector<Eigen::Vector3f>& points, int half_window) {
  const int n = static_cast<int>(points.size());
  std::vector<Eigen::Vector3f> tangents(n);
  for (int k = 0; k < n; ++k) {
    const int first = std::max(0, k - half_window);
    const int last = std::min(n - 1, k + half_window);
    Eigen::Vector3f mean = Eigen::Vector3f::Zero();
    for (int i = first; i <= last; ++i) mean += points[i];
    mean /= static_cast<float>(last - first + 1);
    Eigen::Matrix3f covariance = Eigen::Matrix3f::Zero();
    for (int i = first; i <= last; ++i) {
      const Eigen::Vector3f d = points[i] - mean;
      covariance += d * d.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> solver;
    solver.computeDirect(covariance);
    tangents[k] = solver.eigenvectors().col(2).normalized();  // Largest eigenvalue last.
  }
  return tangents;
}

}  // namespace

std::vector<Curve> linkCurves(const Cloud& cloud, const std::vector<int>& boundary,
                              const NormalEdgeCurveParams& params) {
  return linkCurves(cloud, boundary, std::vector<int>(cloud.size(), 1), params);
}

std::vector<Curve> linkCurves(const Cloud& cloud, const std::vector<int>& boundary, const std::vector<int>& labels,
                              const NormalEdgeCurveParams& params) {
  std::vector<Curve> curves;
  if (boundary.empty()) return curves;
  std::vector<Eigen::Vector3f> positions;
  std::vector<int> segment;
  positions.reserve(boundary.size());
  segment.reserve(boundary.size());
  for (int index : boundary) {
    positions.push_back(cloud.points[index].getVector3fMap());
    segment.push_back(labels[index]);
  }
  const Adjacency tree = minimumSpanningForest(positions, segment, params.curve_link_radius);

  // Peel the forest: the longest path of a part of the tree becomes a curve, its points leave
  // the tree, and the branches left behind are peeled in turn.
  const int n = static_cast<int>(positions.size());
  std::vector<char> alive(n, 1);
  std::vector<float> distance(n, 0.0f);
  std::vector<int> parent(n, -1);
  for (int seed = 0; seed < n; ++seed) {
    while (alive[seed]) {
      const int end = farthestVertex(tree, alive, seed, distance, parent);
      const int start = farthestVertex(tree, alive, end, distance, parent);
      std::vector<int> path;
      for (int v = start; v != -1; v = parent[v]) {
        path.push_back(v);
        alive[v] = 0;
      }
      if (static_cast<int>(path.size()) < params.min_curve_points) continue;
      // Orient each curve from its lower index end, so the order does not depend on the walk.
      if (path.front() > path.back()) std::reverse(path.begin(), path.end());
      Curve curve;
      std::vector<Eigen::Vector3f> curve_points;
      for (int v : path) {
        curve.points.push_back(boundary[v]);
        curve_points.push_back(positions[v]);
      }
      curve.tangents = curveTangents(curve_points, params.tangent_half_window);
      curves.push_back(std::move(curve));
    }
  }
  return curves;
}

}  // namespace symmetry_segmentation
