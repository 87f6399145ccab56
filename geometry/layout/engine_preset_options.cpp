#include "geometry/layout/engine_preset_options.h"

#include "geometry/survey/blended_error.h"
#include "geometry/survey/capture_sights.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

namespace probeproxy {

namespace {

struct Reach {  // one option at one sample: its own fade there, and what it shows
  int option = 0;
  double fade = 0.0;
  ProbeSight sight;
};

struct SampleReach {
  std::vector<Reach> options;  // in the engine's order
  std::vector<int> active;     // places in `options` of those some probe has, ascending
  // The place of the first active option whose fade is full (EngineModel::fullFade): the
  // options after it get nothing here. INT_MAX: none is.
  int full = std::numeric_limits<int>::max();
  FadeSums sums;  // of the active options
  double areaSquareMeters = 0.0;
};

struct At {  // an option at a sample
  std::size_t sample = 0;
  int place = 0;  // in the sample's options
};

// A sample a move changes, with the places there of the option given up and the one taken
// (-1: not at this sample).
struct Change {
  std::size_t sample = 0;
  int off = -1, on = -1;
};

// Whether the change happens behind the sample's full option, where it changes nothing.
bool behindFull(const Change& c, const SampleReach& s) {
  return (c.off < 0 || c.off > s.full) && (c.on < 0 || c.on > s.full);
}

// The sample's floor that does not get the reflection right: the fallback's share, the share
// of probes that cannot see the true hit (they show what stands in front of it), and the rest
// where its error is over the tolerance. The survey reports the hidden share apart from its
// error (`occluded`); a search that left it out would leave out the probes that see the floor
// and keep those that cannot.
double badArea(const SurveySampleError& e, double areaSquareMeters, double toleranceDeg) {
  double bad = (e.uncoveredWeight + e.occludedWeight) * areaSquareMeters;
  if (!std::isnan(e.errorDeg) && e.errorDeg > toleranceDeg)
    bad += areaSquareMeters * (1.0 - e.occludedWeight - e.uncoveredWeight);
  return bad;
}

// Stale probes judged again together (in parallel) when one of them comes to the top.
constexpr std::size_t kJudgedAtOnce = 8;

struct Move {
  int target = -1;  // the option the probe moves to, -1: left out
  double gain = 0.0;
};

class OptionSearch {
 public:
  OptionSearch(const EngineModel& model, std::span<const int> probeOf, std::vector<int> start,
               const SurveyFloor& floor, const LevelRayCaster& level, CaptureSights& sights,
               double toleranceDeg, std::size_t keptProbes)
      : model_(model),
        probeOf_(probeOf),
        toleranceDeg_(toleranceDeg),
        keptProbes_(keptProbes),
        chosen_(std::move(start)),
        optionsOf_(chosen_.size()),
        reach_(floor.samples.size()),
        samplesOf_(model.probes.size()),
        active_(model.probes.size(), 0),
        bad_(floor.samples.size()),
        best_(chosen_.size()),
        stale_(chosen_.size(), 0) {
    for (std::size_t j = 0; j < probeOf_.size(); ++j)
      optionsOf_.at(static_cast<std::size_t>(probeOf_[j])).push_back(static_cast<int>(j));
    for (const int c : chosen_)
      if (c >= 0) active_.at(static_cast<std::size_t>(c)) = 1;
    // The options of one probe share its capture point (but EEVEE's captured at their box's
    // centre): the ray from it to a sample's true hit is cast once, here and in the surveys
    // that share `sights`.
    const std::vector<std::uint32_t> captureOf = sights.idsOf(model_.probes);
    tbb::parallel_for(std::size_t{0}, reach_.size(), [&](std::size_t i) {
      const ReflectionSample& s = floor.samples[i].sample;
      for (const ProbeFade& f : model_.fades(s.xMeters, s.eyeMeters)) {
        const auto option = static_cast<std::size_t>(f.probe);
        const ProbeSight sight = engineProbeSight(
            model_.probes[option], s, [&] { return sights.hidden(level, i, captureOf[option]); });
        reach_[i].options.push_back({f.probe, f.fade, sight});
      }
      reach_[i].areaSquareMeters = floor.samples[i].areaSquareMeters;
      for (std::size_t k = 0; k < reach_[i].options.size(); ++k)
        if (active_[static_cast<std::size_t>(reach_[i].options[k].option)])
          reach_[i].active.push_back(static_cast<int>(k));
      settle(reach_[i]);
      bad_[i] = badAreaWith(i, -1, -1);
    });
    for (std::size_t i = 0; i < reach_.size(); ++i) {
      floorArea_ += reach_[i].areaSquareMeters;
      for (std::size_t k = 0; k < reach_[i].options.size(); ++k)
        samplesOf_[static_cast<std::size_t>(reach_[i].options[k].option)].push_back(
            {i, static_cast<int>(k)});
    }
  }

  // Lazily: a probe whose options' samples a move changed keeps its old best move, marked
  // stale, until it comes to the top; before stopping, every stale probe is judged again.
  std::vector<int> run() {
    std::vector<int> all(chosen_.size());
    for (std::size_t p = 0; p < all.size(); ++p) all[p] = static_cast<int>(p);
    judge(all);
    for (;;) {
      std::vector<int> order = all;
      std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return best_[static_cast<std::size_t>(a)].gain > best_[static_cast<std::size_t>(b)].gain;
      });
      if (order.empty()) break;
      const std::size_t top = static_cast<std::size_t>(order.front());
      const bool worth = best_[top].gain >= kLeastOptionGain * floorArea_;
      std::vector<int> again;
      for (const int p : order) {
        if (worth && again.size() == kJudgedAtOnce) break;
        if (stale_[static_cast<std::size_t>(p)]) again.push_back(p);
      }
      if (worth && !stale_[top]) {
        move(static_cast<int>(top), best_[top].target);
      } else if (!again.empty()) {
        judge(again);
      } else {
        break;
      }
    }
    return chosen_;
  }

 private:
  // Each probe's best move, afresh.
  void judge(const std::vector<int>& probes) {
    tbb::parallel_for(std::size_t{0}, probes.size(), [&](std::size_t k) {
      const std::size_t p = static_cast<std::size_t>(probes[k]);
      best_[p] = bestMove(probes[k]);
      stale_[p] = 0;
    });
  }

  // The sample's full option and sums, from its active options (the first mostProbes).
  void settle(SampleReach& s) const {
    s.full = std::numeric_limits<int>::max();
    s.sums = {};
    for (const int k : s.active) {
      const Reach& r = s.options[static_cast<std::size_t>(k)];
      if (r.fade >= model_.fullFade) s.full = std::min(s.full, k);  // active is ascending
      if (model_.mostProbes == 0 || s.sums.count < static_cast<int>(model_.mostProbes))
        s.sums.add(r.fade, r.sight, +1);
    }
  }

  // The sample's bad floor with the options now active, the one at place `off` given up and
  // the one at place `on` taken (-1: none). Where the engine takes only the first few probes
  // at a point (Godot 3's 8 an object), a sample more boxes hold counts its floor once more for
  // each box too many: which of them the engine takes there depends on how the level's meshes
  // are cut, which the export does not fix, and a box given up anywhere in the crowd counts.
  double badAreaWith(std::size_t sample, int off, int on) const {
    const SampleReach& s = reach_[sample];
    double crowd = 0.0;
    const std::size_t most = model_.mostProbes;
    const std::size_t count = s.active.size() - (off >= 0 ? 1 : 0) + (on >= 0 ? 1 : 0);
    if (most > 0 && count > most) crowd = static_cast<double>(count - most) * s.areaSquareMeters;
    if (model_.averagesFades) {
      FadeSums sums = s.sums;
      if (most > 0 && s.active.size() + (on >= 0 ? 1 : 0) > most) {
        // The first `most` may change with the move: summed again.
        sums = {};
        const auto add = [&](int k) {
          if (sums.count < static_cast<int>(most))
            sums.add(s.options[static_cast<std::size_t>(k)].fade,
                     s.options[static_cast<std::size_t>(k)].sight, +1);
        };
        for (const int k : s.active) {
          if (on >= 0 && on < k) add(std::exchange(on, -1));
          if (k != off) add(k);
        }
        if (on >= 0) add(on);
        return crowd + badArea(sums.averaged(), s.areaSquareMeters, toleranceDeg_);
      }
      for (const auto& [k, sign] : {std::pair{off, -1}, std::pair{on, +1}})
        if (k >= 0)
          sums.add(s.options[static_cast<std::size_t>(k)].fade,
                   s.options[static_cast<std::size_t>(k)].sight, sign);
      return crowd + badArea(sums.averaged(), s.areaSquareMeters, toleranceDeg_);
    }
    thread_local std::vector<ProbeFade> fades;  // no allocation per call
    fades.clear();
    // Each fade labelled by its place in s.options (the composition only carries labels), in
    // the engine's order, up to the first full one.
    bool full = false;
    const auto take = [&](int k) {
      const double fade = s.options[static_cast<std::size_t>(k)].fade;
      fades.push_back({k, fade});
      full = fade >= model_.fullFade;
    };
    for (const int k : s.active) {
      if (on >= 0 && on < k) {
        take(on);
        on = -1;
        if (full) break;
      }
      if (k != off) take(k);
      if (full) break;
    }
    if (on >= 0 && !full) take(on);
    const EngineBlend blend = model_.compose(fades);
    const SurveySampleError e = sampleErrorOfBlend(blend.weights, blend.fallbackWeight, [&](int k) {
      return s.options[static_cast<std::size_t>(k)].sight;
    });
    return crowd + badArea(e, s.areaSquareMeters, toleranceDeg_);
  }

  // The samples either option reaches, ascending, with each one's place there.
  std::vector<Change> changes(int off, int on) const {
    static const std::vector<At> none;
    const auto& a = off < 0 ? none : samplesOf_[static_cast<std::size_t>(off)];
    const auto& b = on < 0 ? none : samplesOf_[static_cast<std::size_t>(on)];
    std::vector<Change> out;
    std::size_t i = 0, j = 0;
    while (i < a.size() || j < b.size()) {
      if (j == b.size() || (i < a.size() && a[i].sample < b[j].sample)) {
        out.push_back({a[i].sample, a[i].place, -1});
        ++i;
      } else if (i == a.size() || b[j].sample < a[i].sample) {
        out.push_back({b[j].sample, -1, b[j].place});
        ++j;
      } else {
        out.push_back({a[i].sample, a[i].place, b[j].place});
        ++i, ++j;
      }
    }
    return out;
  }

  // The probe's move that saves the most bad floor: to each of its other options in turn, then
  // out (unless it is kept).
  Move bestMove(int probe) const {
    const int current = chosen_[static_cast<std::size_t>(probe)];
    std::vector<int> targets = optionsOf_[static_cast<std::size_t>(probe)];
    if (static_cast<std::size_t>(probe) >= keptProbes_) targets.push_back(-1);
    Move best{current, -INFINITY};
    for (const int target : targets) {
      if (target == current) continue;
      double gain = 0.0;
      for (const Change& c : changes(current, target))
        if (!behindFull(c, reach_[c.sample]))
          gain += bad_[c.sample] - badAreaWith(c.sample, c.off, c.on);
      if (gain > best.gain) best = {target, gain};
    }
    return best;
  }

  // Moves `probe` to `target`; the probes with an option on the samples that changes are
  // stale.
  void move(int probe, int target) {
    const int current = chosen_[static_cast<std::size_t>(probe)];
    if (current >= 0) active_[static_cast<std::size_t>(current)] = 0;
    if (target >= 0) active_[static_cast<std::size_t>(target)] = 1;
    chosen_[static_cast<std::size_t>(probe)] = target;
    for (const Change& c : changes(current, target)) {
      std::vector<int>& active = reach_[c.sample].active;
      if (c.off >= 0) active.erase(std::find(active.begin(), active.end(), c.off));
      if (c.on >= 0) active.insert(std::upper_bound(active.begin(), active.end(), c.on), c.on);
      settle(reach_[c.sample]);
      bad_[c.sample] = badAreaWith(c.sample, -1, -1);
      for (const Reach& r : reach_[c.sample].options)
        stale_[static_cast<std::size_t>(probeOf_[static_cast<std::size_t>(r.option)])] = 1;
    }
    stale_[static_cast<std::size_t>(probe)] = 1;
  }

  const EngineModel& model_;
  std::span<const int> probeOf_;
  double toleranceDeg_ = 0.0;
  std::size_t keptProbes_ = 0;               // probes never left out
  std::vector<int> chosen_;                  // per probe: its option, -1 none
  std::vector<std::vector<int>> optionsOf_;  // per probe, ascending
  std::vector<SampleReach> reach_;           // per sample
  std::vector<std::vector<At>> samplesOf_;   // per option, the samples it reaches, ascending
  std::vector<char> active_;                 // per option: some probe has it
  std::vector<double> bad_;                  // per sample, with the active options
  std::vector<Move> best_;                   // per probe
  std::vector<char> stale_;                  // per probe: best_ from before a move
  double floorArea_ = 0.0;
};

}  // namespace

std::vector<int> chooseEngineOptions(const EngineModel& model, std::span<const int> probeOf,
                                     std::vector<int> start, const SurveyFloor& floor,
                                     const LevelRayCaster& level, double toleranceDeg,
                                     std::size_t keptProbes, CaptureSights* sights) {
  if (probeOf.size() != model.probes.size())
    throw std::invalid_argument("chooseEngineOptions: one probe per option");
  if (!model.fades || !model.compose) return start;
  std::optional<CaptureSights> own;  // a table of its own only when none is shared
  if (!sights) sights = &own.emplace(floor);
  return OptionSearch(model, probeOf, std::move(start), floor, level, *sights, toleranceDeg,
                      keptProbes)
      .run();
}

}  // namespace probeproxy
