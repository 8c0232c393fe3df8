// Stage 4, cut: graph-cut segmentation of the working cloud for one symmetry plane (paper eq. 7-12).
// Nodes are points; source = foreground. Unary costs come from ReflectionDataTerm, pairwise
// links are the k-NN smoothness links (eq. 11, precomputed) and, per plane, symmetric links
// between a point and the point its reflection lands on (eq. 12).
#include "symmetry_segmentation/symmetry/symmetric_graph_cut.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <maxflow/graph.h>

#include "symmetry_segmentation/parallel_for.h"
#include "symmetry_segmentation/symmetry/pipeline_state.h"
#include "symmetry_segmentation/symmetry/smoothness_weight.h"
#include "symmetry_segmentation/symmetry/strongest_component.h"

namespace symmetry_segmentation {
namespace {

using FlowGraph = maxflow::Graph<double, double, double>;

void throwMaxflowError(const char* message) {
  throw std::runtime_error(std::string("max-flow: ") + message);
}

bool isFinitePoint(const PointT& point) {
  return point.getVector3fMap().allFinite() && point.getNormalVector3fMap().allFinite();
}

/// Per point: whether no other finite point lies within `radius` (0: none is isolated).
std::vector<char> isolatedPoints(const Cloud& cloud, const pcl::KdTreeFLANN<PointT>& tree, float radius) {
  std::vector<char> isolated(cloud.size(), 0);
  if (!(radius > 0.0f)) return isolated;
  std::vector<int> indices;
  std::vector<float> squared;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!isFinitePoint(cloud.points[i])) continue;
    // Itself and nothing else (the tree may hold points whose normal is NaN: they count too).
    isolated[i] = tree.radiusSearch(cloud.points[i], radius, indices, squared, 2) < 2;
  }
  return isolated;
}

/// k nearest other points of every point within `max_distance` (0: any distance), made
/// symmetric (j in N(i) <=> i in N(j)), sorted; isolated points get none. Without the bound, an
/// isolated voxel of sensor noise above the table is the neighbour of whatever surface is
/// nearest, however far, and the cut's smoothness term pulls it into that object.
std::vector<std::vector<int>> symmetricKnn(const Cloud& cloud, const pcl::KdTreeFLANN<PointT>& tree, int k,
                                           float max_distance, const std::vector<char>& isolated) {
  const float max_squared = max_distance * max_distance;
  const int n = static_cast<int>(cloud.size());
  std::vector<std::vector<int>> neighbours(n);
  if (k <= 0) return neighbours;
  std::vector<int> indices;
  std::vector<float> squared;
  for (int i = 0; i < n; ++i) {
    if (!isFinitePoint(cloud.points[i]) || isolated[i]) continue;
    const int found = tree.nearestKSearch(cloud.points[i], k + 1, indices, squared);
    int taken = 0;
    for (int f = 0; f < found && taken < k; ++f) {
      const int j = indices[f];
      if (j == i || !isFinitePoint(cloud.points[j]) || isolated[j]) continue;
      if (max_distance > 0.0f && squared[f] > max_squared) break;  // sorted by distance
      neighbours[i].push_back(j);
      neighbours[j].push_back(i);
      ++taken;
    }
  }
  for (auto& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return neighbours;
}

}  // namespace

SymmetricGraphCut::SymmetricGraphCut(Cloud::ConstPtr cloud, const OccupancyMap& occupancy,
                                     std::optional<TableTop> table, const SymmetryCutParams& params)
    : cloud_(std::move(cloud)), occupancy_(occupancy), table_(std::move(table)), params_(params) {
  if (!cloud_) throw std::invalid_argument("SymmetricGraphCut needs a cloud");
  for (const auto& point : cloud_->points) {
    if (isFinitePoint(point)) cloud_box_.extend(point.getVector3fMap());
  }
  // Reflections that matter land within dbuf of the cloud (farther ones are judged free or
  // unknown by the map itself); below the table they are decided by the table's top. The 2 cm
  // beyond is fixed slack of the cache, not a tunable: the answers are the map's either way.
  Eigen::AlignedBox3f reach = cloud_box_;
  if (!reach.isEmpty()) {
    const Eigen::Vector3f margin = Eigen::Vector3f::Constant(params_.dbuf + params_.dmax + 0.02f);
    reach = Eigen::AlignedBox3f(reach.min() - margin, reach.max() + margin);
  }
  occupancy_grid_ = std::make_unique<OccupancyGrid>(occupancy_, reach);
  if (cloud_->empty()) return;
  tree_.setInputCloud(cloud_);
  grid_ = PointGrid(*cloud_, params_.dbuf);
  // A point with nothing near it is a depth camera's flying pixel or speckle (real Kinect frames
  // hold tens, simulated RealSense ones hundreds): linked to whatever surface is nearest it
  // joins, and chains of them join objects, so it takes part in no cut.
  isolated_ = isolatedPoints(*cloud_, tree_, params_.isolated_radius);
  neighbours_ = symmetricKnn(*cloud_, tree_, params_.neighbours, params_.max_neighbour_distance, isolated_);
  for (int a = 0; a < static_cast<int>(neighbours_.size()); ++a) {
    const PointT& p = cloud_->points[a];
    for (int b : neighbours_[a]) {
      if (b <= a) continue;
      const PointT& q = cloud_->points[b];
      smooth_links_.push_back({a, b,
                               smoothnessWeight(p.getVector3fMap(), p.getNormalVector3fMap(), q.getVector3fMap(),
                                                q.getNormalVector3fMap(), params_)});
    }
  }
}

ReflectionDataTerm SymmetricGraphCut::dataTermView() const {
  return ReflectionDataTerm(*cloud_, grid_, cloud_box_, *occupancy_grid_, table_, params_);
}

ReflectionEvidence SymmetricGraphCut::dataTerm(int index, const SymmetryPlane& plane) const {
  return dataTermView().evaluate(index, plane);
}

std::vector<int> SymmetricGraphCut::segment(const SymmetryPlane& plane, const std::vector<int>& anchor) const {
  const int n = static_cast<int>(cloud_->size());
  const ReflectionDataTerm data_term = dataTermView();
  std::vector<ReflectionEvidence> evidence(n);
  std::vector<float> support(n, 0.0f);
  bool any_support = false;
  for (int i = 0; i < n; ++i) {
    if (isolated_[i]) {
      evidence[i].cost_foreground = 1.0f;  // no links either: always background
      continue;
    }
    evidence[i] = data_term.evaluate(i, plane);
    support[i] = evidence[i].foreground_strength;
    any_support = any_support || support[i] > 0.0f;
  }
  // Every foreground cost is >= 0 and every background cost 0: the empty cut is optimal.
  if (!any_support) return {};

  // Symmetric links (eq. 12), each pair once. The strength is the same from both ends since
  // reflection preserves angles.
  std::vector<std::pair<int, int>> symmetric_links;
  std::vector<float> symmetric_weights;
  for (int i = 0; i < n; ++i) {
    const int j = evidence[i].match;
    if (j < 0 || j == i || isolated_[j] || evidence[i].foreground_strength <= 0.0f) continue;
    if (evidence[j].match == i && evidence[j].foreground_strength > 0.0f && j < i) continue;  // added from j
    symmetric_links.emplace_back(i, j);
    symmetric_weights.push_back(params_.lambda_sym * evidence[i].foreground_strength);
  }

  FlowGraph graph(n, static_cast<int>(smooth_links_.size() + symmetric_links.size()), throwMaxflowError);
  graph.add_node(n);
  for (int i = 0; i < n; ++i) {
    // Source side = foreground: labelling i foreground cuts its sink link, so that carries cost(FG).
    graph.add_tweights(i, evidence[i].cost_background, evidence[i].cost_foreground);
  }
  for (const SmoothLink& link : smooth_links_) graph.add_edge(link.a, link.b, link.weight, link.weight);
  for (std::size_t l = 0; l < symmetric_links.size(); ++l) {
    graph.add_edge(symmetric_links[l].first, symmetric_links[l].second, symmetric_weights[l], symmetric_weights[l]);
  }
  graph.maxflow();

  std::vector<char> foreground(n, 0);
  for (int i = 0; i < n; ++i) {
    // Ties (e.g. points with no evidence and no link to any) go to the background.
    foreground[i] = graph.what_segment(i, FlowGraph::SINK) == FlowGraph::SOURCE;
  }
  return strongestForegroundComponent(foreground, neighbours_, symmetric_links, support, anchor);
}

void GraphCutStage::run(PipelineState& state) const {
  const std::size_t first = state.candidates.size();
  state.candidates.resize(state.hypotheses.size());
  parallelFor(state.hypotheses.size() - first, state.threads, [&](std::size_t k) {
    const std::size_t i = first + k;
    CandidateSegment& candidate = state.candidates[i];
    candidate.plane = state.hypotheses[i].plane;
    candidate.points = state.graph->segment(candidate.plane, state.hypotheses[i].anchor);
    if (static_cast<int>(candidate.points.size()) >= filter_.min_segment_points) {
      candidate.scores = state.evidence->scores(candidate.points, candidate.plane);
    }
  });
  state.count("cuts", state.hypotheses.size() - first);
}

}  // namespace symmetry_segmentation
