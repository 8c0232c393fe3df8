// Keeps the best-supported connected foreground component of a cut.
#include "symmetry_segmentation/symmetry/strongest_component.h"

#include <numeric>

namespace symmetry_segmentation {
namespace {

int findRoot(std::vector<int>& parent, int i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];  // path halving
    i = parent[i];
  }
  return i;
}

void unite(std::vector<int>& parent, int a, int b) {
  a = findRoot(parent, a);
  b = findRoot(parent, b);
  if (a == b) return;
  // The smaller index becomes the root, so the result does not depend on the link order.
  if (a < b) parent[b] = a; else parent[a] = b;
}

}  // namespace

std::vector<int> strongestForegroundComponent(const std::vector<char>& foreground,
                                              const std::vector<std::vector<int>>& neighbours,
                                              const std::vector<std::pair<int, int>>& links,
                                              const std::vector<float>& support,
                                              const std::vector<int>& anchor) {
  const int n = static_cast<int>(foreground.size());
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  for (int i = 0; i < n; ++i) {
    if (!foreground[i]) continue;
    for (int j : neighbours[i]) {
      if (j > i && foreground[j]) unite(parent, i, j);
    }
  }
  for (const auto& [a, b] : links) {
    if (foreground[a] && foreground[b]) unite(parent, a, b);
  }

  std::vector<double> component_support(n, 0.0);
  for (int i = 0; i < n; ++i) {
    if (foreground[i]) component_support[findRoot(parent, i)] += support[i];
  }
  std::vector<int> anchored(n, 0);
  for (int i : anchor) {
    if (i >= 0 && i < n && foreground[i]) ++anchored[findRoot(parent, i)];
  }
  int best = -1;
  for (int i = 0; i < n; ++i) {
    if (component_support[i] <= 0.0) continue;
    const bool better = best < 0 || anchored[i] > anchored[best] ||
                        (anchored[i] == anchored[best] && component_support[i] > component_support[best]);
    if (better) best = i;
  }
  std::vector<int> kept;
  if (best < 0) return kept;
  for (int i = 0; i < n; ++i) {
    if (foreground[i] && findRoot(parent, i) == best) kept.push_back(i);
  }
  return kept;
}

}  // namespace symmetry_segmentation
