#pragma once
// One step of the symmetry method. The method is a list of stages (symmetry.stages in the
// configuration), run in order on one pipeline state (pipeline_state.h); each stage has a name,
// its own parameters (symmetry_params.h) and says which products of the state it needs and which
// it makes, so a list is checked before anything runs. The catalog (stage_catalog.cpp) knows
// every stage; the README's method section lists the default list, one line per stage.

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace symmetry_segmentation {

struct PipelineState;
struct SegmentationConfig;

class Stage {
 public:
  virtual ~Stage() = default;
  /// Works on `state`; counts what it did with state.count().
  virtual void run(PipelineState& state) const = 0;
};

/// What the state holds once some stage has made it.
enum class Product { Surfaces, Curves, Islands, Hypotheses, Candidates, Segments };

enum class StageKind {
  Features,           ///< Scene structure later stages use (curves, islands).
  HypothesisSource,   ///< Adds symmetry planes to try.
  CandidateProducer,  ///< Cuts (or re-cuts) the planes not yet cut into candidate segments.
  CandidateFilter,    ///< Keeps the candidates that look like whole objects as the segments.
  SegmentRewriter,    ///< Splits, merges, adds or trims the segments.
};

struct StageInfo {
  std::string name;
  StageKind kind;
  std::string summary;  ///< What it does and why, one line.
  std::vector<Product> needs;
  std::vector<Product> makes;
  std::function<std::unique_ptr<Stage>(const SegmentationConfig&)> make;
};

/// Every stage, in the order of the default list.
const std::vector<StageInfo>& stageCatalog();
/// nullptr for an unknown name.
const StageInfo* findStage(const std::string& name);
const char* productName(Product product);
const char* stageKindName(StageKind kind);

/// The stages of `config.symmetry.stages`, ready to run. Throws InputError when the list cannot run.
std::vector<std::unique_ptr<Stage>> makeStages(const SegmentationConfig& config);

}  // namespace symmetry_segmentation
