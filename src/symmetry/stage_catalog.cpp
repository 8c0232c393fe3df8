// Every stage of the symmetry method, in the order of the default list: what it needs and makes,
// and how it is made from the configuration. Adding a stage: its unit (header, source, a
// parameter struct in symmetry_params.h with its section in parameter_schema.cpp) and a line here.
#include "symmetry_segmentation/symmetry/stage.h"

#include <algorithm>
#include <map>

#include "symmetry_segmentation/errors.h"
#include "symmetry_segmentation/segmentation_config.h"
#include "symmetry_segmentation/symmetry/coaxial_pieces.h"
#include "symmetry_segmentation/symmetry/color_seams.h"
#include "symmetry_segmentation/symmetry/completion.h"
#include "symmetry_segmentation/symmetry/composite_segments.h"
#include "symmetry_segmentation/symmetry/duplicate_segments.h"
#include "symmetry_segmentation/symmetry/footprint_hypotheses.h"
#include "symmetry_segmentation/symmetry/occluder_gaps.h"
#include "symmetry_segmentation/symmetry/island_segments.h"
#include "symmetry_segmentation/symmetry/islands.h"
#include "symmetry_segmentation/symmetry/mirror_twins.h"
#include "symmetry_segmentation/symmetry/nested_segments.h"
#include "symmetry_segmentation/symmetry/object_size.h"
#include "symmetry_segmentation/symmetry/normal_edge_curves.h"
#include "symmetry_segmentation/symmetry/object_bottom_stage.h"
#include "symmetry_segmentation/symmetry/plane_refinement.h"
#include "symmetry_segmentation/symmetry/segment_filter.h"
#include "symmetry_segmentation/symmetry/stray_color_pieces.h"
#include "symmetry_segmentation/symmetry/symmetric_graph_cut.h"
#include "symmetry_segmentation/symmetry/symmetry_hypotheses.h"
#include "symmetry_segmentation/symmetry/upright_hypotheses.h"

namespace symmetry_segmentation {
namespace {

using P = Product;
using K = StageKind;
using Config = SegmentationConfig;

template <typename StageType, typename... Args>
std::unique_ptr<Stage> made(Args&&... args) {
  return std::make_unique<StageType>(std::forward<Args>(args)...);
}

}  // namespace

const std::vector<StageInfo>& stageCatalog() {
  static const std::vector<StageInfo> catalog = {
      {"curves", K::Features, "normal-edge curves: supervoxels merged into surfaces, their boundaries linked into curves (paper)",
       {}, {P::Surfaces, P::Curves},
       [](const Config& c) { return made<NormalEdgeCurveStage>(c.symmetry.curves); }},
      {"curve_pairs", K::HypothesisSource, "planes from curve pairs matched point by point, mean-shift clustered (paper)",
       {P::Curves}, {P::Hypotheses},
       [](const Config& c) { return made<CurvePairStage>(c.symmetry.curve_pairs); }},
      {"upright", K::HypothesisSource, "vertical planes from single surfaces: axes of revolution, face bisectors (needs the table)",
       {P::Surfaces}, {P::Hypotheses},
       [](const Config& c) { return made<UprightStage>(c.symmetry.upright, c.preprocessing.voxel_size); }},
      {"cut", K::CandidateProducer, "graph cut per hypothesis not cut yet, with the candidate's scores (paper)",
       {P::Hypotheses}, {P::Candidates},
       [](const Config& c) { return made<GraphCutStage>(c.symmetry.filter); }},
      {"refine", K::CandidateProducer, "plane refined by ICP of the candidate with its reflection, then cut again (paper)",
       {P::Candidates}, {},
       [](const Config& c) { return made<RefineStage>(c.symmetry.refine, c.symmetry.filter); }},
      {"islands", K::Features, "groups of points apart from all others, often exactly one object",
       {}, {P::Islands},
       [](const Config& c) { return made<IslandStage>(c.symmetry.islands, c.symmetry.filter); }},
      {"footprints", K::HypothesisSource, "vertical planes through the footprint of islands no passing candidate covers",
       {P::Candidates, P::Islands}, {P::Hypotheses},
       [](const Config& c) { return made<FootprintStage>(c.symmetry.footprints, c.symmetry.filter); }},
      {"occluder_gaps", K::CandidateProducer, "the plane across the hidden gap between two passing pieces that do not touch, cut; kept when the cut takes both",
       {P::Candidates}, {P::Candidates},
       [](const Config& c) { return made<OccluderGapStage>(c.symmetry.occluder_gaps, c.symmetry.filter, c.symmetry.dedup); }},
      {"filter", K::CandidateFilter, "candidates whose occlusion and smoothness scores pass become the segments (paper)",
       {P::Candidates}, {P::Segments},
       [](const Config& c) { return made<FilterStage>(c.symmetry.filter); }},
      {"island_segments", K::SegmentRewriter, "an island one found plane explains whole is added as a segment",
       {P::Candidates, P::Islands, P::Segments}, {},
       [](const Config& c) { return made<IslandSegmentStage>(c.symmetry.island_segments, c.symmetry.filter); }},
      {"mirror_twins", K::SegmentRewriter, "two like objects the plane between them mirrors onto each other are split",
       {P::Segments}, {},
       [](const Config& c) { return made<MirrorTwinStage>(c.symmetry.mirror_twins); }},
      {"composites", K::SegmentRewriter, "a segment of two objects found alone, meeting at a concave seam, is split",
       {P::Segments}, {},
       [](const Config& c) { return made<CompositeStage>(c.symmetry.composites); }},
      {"nested", K::SegmentRewriter, "an object glued onto another's segment, found alone inside it, is taken out",
       {P::Segments}, {},
       [](const Config& c) { return made<NestedStage>(c.symmetry.nested, c.symmetry.filter); }},
      {"color_seams", K::SegmentRewriter, "flush objects of different colours are split at their colour seam",
       {P::Candidates, P::Segments}, {},
       [](const Config& c) { return made<ColorSeamStage>(c.symmetry.color_seams, c.symmetry.filter, c.preprocessing.voxel_size,
                                                c.symmetry.composites.min_color_overlap);
       }},
      {"coaxial_pieces", K::SegmentRewriter, "segments sharing a vertical axis of revolution and nearly touching (a bowl's inner and outer wall) are joined, and so is a round body's handle",
       {P::Segments}, {},
       [](const Config& c) { return made<CoaxialPieceStage>(c.symmetry.coaxial_pieces, c.symmetry.upright, c.symmetry.filter); }},
      {"object_size", K::SegmentRewriter, "a segment larger than a graspable object, mostly one wide plane, a scrap of the table's noise, hanging over the table or rising from below past its edge is dropped; a segment sheds the table's specks first",
       {P::Segments}, {},
       [](const Config& c) { return made<ObjectSizeStage>(c.symmetry.object_size, c.preprocessing.voxel_size); }},
      {"dedup", K::SegmentRewriter, "of segments overlapping by most of the smaller, the cleanest boundary stays (paper)",
       {P::Segments}, {},
       [](const Config& c) { return made<DuplicateStage>(c.symmetry.dedup); }},
      {"stray_color_pieces", K::SegmentRewriter, "a strip of the next object's colour moves to that object",
       {P::Segments}, {},
       [](const Config& c) { return made<StrayColorStage>(c.symmetry.stray_color_pieces); }},
      {"object_bottoms", K::SegmentRewriter, "each segment gets back its sides' points and inside floor within the table margin",
       {P::Segments}, {},
       [](const Config& c) { return made<ObjectBottomStage>(c.object_bottoms, c.preprocessing.voxel_size); }},
      {"completion", K::SegmentRewriter, "each segment's unseen side: its reflections (and turned copies, about an axis of revolution) into unobserved space; the completed box and symmetry frame",
       {P::Segments}, {},
       [](const Config& c) {
         return made<CompletionStage>(c.symmetry.completion, c.symmetry.upright, c.symmetry.coaxial_pieces.min_axis_share,
                                      c.preprocessing.voxel_size);
       }},
  };
  return catalog;
}

const StageInfo* findStage(const std::string& name) {
  for (const StageInfo& info : stageCatalog()) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

const char* productName(Product product) {
  switch (product) {
    case P::Surfaces: return "surfaces";
    case P::Curves: return "curves";
    case P::Islands: return "islands";
    case P::Hypotheses: return "hypotheses";
    case P::Candidates: return "candidates";
    case P::Segments: return "segments";
  }
  return "?";
}

const char* stageKindName(StageKind kind) {
  switch (kind) {
    case K::Features: return "features";
    case K::HypothesisSource: return "hypothesis source";
    case K::CandidateProducer: return "candidate producer";
    case K::CandidateFilter: return "candidate filter";
    case K::SegmentRewriter: return "segment rewriter";
  }
  return "?";
}

std::vector<std::string> stageListProblems(const std::vector<std::string>& stages) {
  std::vector<std::string> problems;
  auto problem = [&problems](const std::string& text) { problems.push_back("symmetry.stages: " + text); };
  std::map<Product, bool> made_so_far;
  std::size_t last_cut = 0;
  for (std::size_t i = 0; i < stages.size(); ++i) {
    if (stages[i] == "cut") last_cut = i + 1;
  }
  bool uncut_hypotheses = false;
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const StageInfo* info = findStage(stages[i]);
    if (!info) {
      std::string known;
      for (const StageInfo& stage : stageCatalog()) known += (known.empty() ? "" : ", ") + stage.name;
      problem("unknown stage '" + stages[i] + "' (known: " + known + ")");
      continue;
    }
    for (Product need : info->needs) {
      if (made_so_far[need]) continue;
      std::string makers;
      for (const StageInfo& stage : stageCatalog()) {
        if (std::count(stage.makes.begin(), stage.makes.end(), need)) makers += (makers.empty() ? "" : ", ") + stage.name;
      }
      problem("'" + info->name + "' (position " + std::to_string(i + 1) + ") needs " + productName(need) +
              ", which no stage before it makes (made by " + makers + ")");
    }
    // occluder_gaps appends a hypothesis with its candidate: hypotheses still waiting for their
    // cut would then be paired with the wrong candidates.
    if (info->name == "occluder_gaps" && uncut_hypotheses) {
      problem("'occluder_gaps' (position " + std::to_string(i + 1) +
              ") needs every earlier hypothesis cut: list a 'cut' between the last hypothesis source and it");
    }
    if (info->kind == K::HypothesisSource) uncut_hypotheses = true;
    if (info->name == "cut") uncut_hypotheses = false;
    for (Product product : info->makes) made_so_far[product] = true;
    if (info->kind == K::HypothesisSource && i + 1 > last_cut) {
      problem("'" + info->name + "' (position " + std::to_string(i + 1) + ") adds hypotheses no later 'cut' cuts");
    }
  }
  // completion describes the final segments: a segment changed after it would keep a stale one.
  const auto completion = std::find(stages.begin(), stages.end(), "completion");
  if (completion != stages.end() && completion + 1 != stages.end()) {
    problem("'completion' (position " + std::to_string(completion - stages.begin() + 1) +
            ") describes the final segments: list it last");
  }
  if (!made_so_far[P::Segments]) problem("no stage makes the segments to report (the list needs 'filter' after 'cut')");
  return problems;
}

std::vector<std::unique_ptr<Stage>> makeStages(const SegmentationConfig& config) {
  const std::vector<std::string> problems = stageListProblems(config.symmetry.stages);
  if (!problems.empty()) {
    std::string message;
    for (const std::string& line : problems) message += (message.empty() ? "" : "; ") + line;
    throw InputError(message);
  }
  std::vector<std::unique_ptr<Stage>> stages;
  for (const std::string& name : config.symmetry.stages) stages.push_back(findStage(name)->make(config));
  return stages;
}

}  // namespace symmetry_segmentation
