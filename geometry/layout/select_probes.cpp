#include "geometry/layout/select_probes.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>
#include <map>
#include <queue>

namespace probeproxy {

namespace {

// Greedy weighted cover with lazy gains: a candidate's gain only shrinks as floor is served, so
// one whose recomputed gain still tops the queue is the best.
void greedyCover(std::span<const CandidateService> services, std::span<const FloorSample> samples,
                 const std::vector<std::vector<std::uint32_t>>& covers, std::vector<char>& covered,
                 std::vector<std::size_t>& chosen, std::size_t maxProbes) {
  const auto gainOf = [&](std::size_t c) {
    double gain = 0.0;
    for (std::uint32_t s : covers[c])
      if (!covered[s]) gain += samples[s].areaSquareMeters;
    return gain;
  };
  using Entry = std::pair<double, std::size_t>;  // gain, candidate
  const auto lower = [](const Entry& a, const Entry& b) {
    return a.first < b.first || (a.first == b.first && a.second > b.second);
  };
  std::priority_queue<Entry, std::vector<Entry>, decltype(lower)> queue(lower);
  for (std::size_t c = 0; c < services.size(); ++c) {
    if (std::find(chosen.begin(), chosen.end(), c) != chosen.end()) continue;
    const double gain = gainOf(c);
    if (gain > 0.0) queue.push({gain, c});
  }
  while (!queue.empty() && (maxProbes == 0 || chosen.size() < maxProbes)) {
    const Entry top = queue.top();
    queue.pop();
    const double gain = gainOf(top.second);
    if (gain <= 0.0) continue;
    if (!queue.empty() && lower(Entry{gain, top.second}, queue.top())) {
      queue.push({gain, top.second});
      continue;
    }
    chosen.push_back(top.second);
    for (std::uint32_t s : covers[top.second]) covered[s] = 1;
  }
}

// Which samples each candidate covers: those it serves within the tolerance, or every one it
// sees.
std::vector<std::vector<std::uint32_t>> coverSets(std::span<const CandidateService> services,
                                                  double toleranceDeg, bool withinTolerance) {
  std::vector<std::vector<std::uint32_t>> covers(services.size());
  for (std::size_t c = 0; c < services.size(); ++c)
    for (std::size_t k = 0; k < services[c].samples.size(); ++k)
      if (!withinTolerance || services[c].errorDeg[k] <= toleranceDeg)
        covers[c].push_back(services[c].samples[k]);
  return covers;
}

// How many chosen probes cover each sample.
std::vector<int> coverCounts(const std::vector<std::vector<std::uint32_t>>& covers,
                             const std::vector<std::size_t>& chosen, std::size_t sampleCount) {
  std::vector<int> counts(sampleCount, 0);
  for (std::size_t c : chosen)
    for (std::uint32_t s : covers[c]) ++counts[s];
  return counts;
}

// Drops, latest first, every probe whose served and seen floor other probes serve and see.
void dropRedundant(const std::vector<std::vector<std::uint32_t>>& serves,
                   const std::vector<std::vector<std::uint32_t>>& sees,
                   std::vector<std::size_t>& chosen, std::size_t sampleCount) {
  std::vector<int> served = coverCounts(serves, chosen, sampleCount);
  std::vector<int> seen = coverCounts(sees, chosen, sampleCount);
  for (std::size_t k = chosen.size(); k-- > 0;) {
    const std::size_t c = chosen[k];
    const auto alsoElsewhere = [](const std::vector<std::uint32_t>& set,
                                  const std::vector<int>& counts) {
      return std::all_of(set.begin(), set.end(), [&](std::uint32_t s) { return counts[s] > 1; });
    };
    if (!alsoElsewhere(serves[c], served) || !alsoElsewhere(sees[c], seen)) continue;
    for (std::uint32_t s : serves[c]) --served[s];
    for (std::uint32_t s : sees[c]) --seen[s];
    chosen.erase(chosen.begin() + static_cast<std::ptrdiff_t>(k));
  }
}

// Whole floor cells go to one probe each, so the regions (and the influence boxes around them)
// stay compact: the probe that serves most of the cell's samples within the tolerance, then
// the one that sees most of them, then the nearest capture point.
std::vector<std::size_t> owners(std::span<const CandidateService> services,
                                std::span<const FloorSample> samples,
                                const std::vector<std::size_t>& chosen, double toleranceDeg) {
  struct Score {
    int served = 0, seen = 0;
  };
  std::map<std::pair<std::size_t, std::size_t>, Score> scores;  // (cell, probe)
  for (std::size_t p = 0; p < chosen.size(); ++p) {
    const CandidateService& s = services[chosen[p]];
    for (std::size_t k = 0; k < s.samples.size(); ++k) {
      Score& score = scores[{samples[s.samples[k]].cell, p}];
      ++score.seen;
      if (s.errorDeg[k] <= toleranceDeg) ++score.served;
    }
  }
  const auto distance2 = [&](std::size_t p, std::size_t sample) {
    const glm::dvec3 d = services[chosen[p]].captureMeters - samples[sample].sample.xMeters;
    return glm::dot(d, d);
  };
  std::vector<std::size_t> owner(samples.size(), 0);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (i > 0 && samples[i].cell == samples[i - 1].cell) {
      owner[i] = owner[i - 1];
      continue;
    }
    const std::size_t cell = samples[i].cell;
    const auto better = [&](std::size_t a, std::size_t b) {  // is probe a a better owner than b?
      const auto sa = scores.find({cell, a}), sb = scores.find({cell, b});
      const Score x = sa == scores.end() ? Score{} : sa->second;
      const Score y = sb == scores.end() ? Score{} : sb->second;
      if (x.served != y.served) return x.served > y.served;
      if (x.seen != y.seen) return x.seen > y.seen;
      return distance2(a, i) < distance2(b, i);
    };
    for (std::size_t p = 1; p < chosen.size(); ++p)
      if (better(p, owner[i])) owner[i] = p;
  }
  return owner;
}

}  // namespace

ProbeSelection selectProbes(std::span<const CandidateService> services,
                            std::span<const FloorSample> samples, double toleranceDeg,
                            std::size_t maxProbes) {
  const auto serves = coverSets(services, toleranceDeg, true);
  const auto sees = coverSets(services, toleranceDeg, false);
  ProbeSelection selection;
  std::vector<char> covered(samples.size(), 0);
  greedyCover(services, samples, serves, covered, selection.chosen, maxProbes);
  // Floor no candidate serves within the tolerance: the candidates that see most of it.
  std::fill(covered.begin(), covered.end(), 0);
  for (std::size_t c : selection.chosen)
    for (std::uint32_t s : sees[c]) covered[s] = 1;
  greedyCover(services, samples, sees, covered, selection.chosen, maxProbes);
  if (maxProbes == 0) dropRedundant(serves, sees, selection.chosen, samples.size());
  selection.owner = owners(services, samples, selection.chosen, toleranceDeg);
  return selection;
}

}  // namespace probeproxy
