// The candidate wire (geometry/layout/candidate_wire.h): what a tile or another process sends
// back reads as exactly what was packed, and bytes it did not write are refused by name.

#include "geometry/layout/candidate_wire.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace probeproxy {
namespace {

// Two capture points: one that sees a wide floor (runs) and one that sees scattered samples
// (an array container), with one and three fit regions.
std::vector<CaptureCandidates> twoCapturePoints() {
  std::vector<CaptureCandidates> captures(2);
  captures[0].capture = 7;
  captures[0].sight.raysCast = 12;
  captures[0].sight.seen.addRange(100, 90'000);
  compact(captures[0].sight.seen);
  CandidateService wide;
  wide.capture = 7;
  wide.fitMeters = 12.5;
  wide.buildMs = 3.25;
  wide.served.addRange(200, 80'000);
  captures[0].services.push_back(wide);
  captures[1].capture = 8;
  for (std::uint32_t i = 3; i < 5'000; i += 7) captures[1].sight.seen.add(i);
  for (double fit : {4.0, 12.0, 30.0}) {
    CandidateService s;
    s.capture = 8;
    s.fitMeters = fit;
    s.buildMs = fit / 3.0;
    for (std::uint32_t i = 3; i < 5'000; i += 14) s.served.add(i);
    captures[1].services.push_back(s);
  }
  return captures;
}

TEST(CandidateWire, ReadsBackExactlyWhatWasPacked) {
  const std::vector<CaptureCandidates> sent = twoCapturePoints();
  const std::string wire = packCandidates(sent);
  const std::vector<CaptureCandidates> got = unpackCandidates(wire);
  ASSERT_EQ(got.size(), sent.size());
  for (std::size_t c = 0; c < sent.size(); ++c) {
    EXPECT_EQ(got[c].capture, sent[c].capture);
    EXPECT_EQ(got[c].sight.raysCast, sent[c].sight.raysCast);
    EXPECT_TRUE(got[c].sight.seen == sent[c].sight.seen);
    ASSERT_EQ(got[c].services.size(), sent[c].services.size());
    for (std::size_t f = 0; f < sent[c].services.size(); ++f) {
      EXPECT_EQ(got[c].services[f].capture, sent[c].capture);
      EXPECT_EQ(got[c].services[f].fitMeters, sent[c].services[f].fitMeters);
      EXPECT_EQ(got[c].services[f].buildMs, sent[c].services[f].buildMs);
      EXPECT_TRUE(got[c].services[f].served == sent[c].services[f].served);
    }
  }
  EXPECT_EQ(packCandidates(got), wire);  // byte for byte
}

TEST(CandidateWire, AWideFloorCostsBytesPerRunNotPerSample) {
  // 89,900 samples seen and 79,800 served: a few runs, not 4 bytes a sample.
  EXPECT_LT(packCandidates(twoCapturePoints()).size(), 4'000u);
}

void expectRefused(const std::string& bytes, const std::string& message) {
  try {
    unpackCandidates(bytes);
    FAIL() << "accepted: " << message;
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(CandidateWire, RefusesBytesItDidNotWrite) {
  const std::string wire = packCandidates(twoCapturePoints());
  expectRefused("JSON{}", "candidate wire: not packed candidates (no PPCW header)");
  std::string future = wire;
  future[4] = 2;
  expectRefused(future, "candidate wire: version 2, this program reads 1");
  expectRefused(wire.substr(0, 30), "candidate wire: 30 bytes end at 24, 8 more expected");
  expectRefused(wire + "x", "candidate wire: 1 bytes after the last capture point");
}

}  // namespace
}  // namespace probeproxy
