#pragma once
// The survey's error map: a top-down picture of the walkable floor, north (+y) up, each floor
// cell coloured by the median error of its samples on a fixed degree scale (the same colours on
// every level, so maps compare by eye), with its legend and a scale bar on the map. Floor no
// influence volume covers is hatched, floor whose true hits no weighted probe sees is grey;
// capture points are white squares with a black centre (with the probe's name on request),
// influence volumes' outer ranges outlined whole in the probe's colour
// (core/blend/weight_picture.h's palette). One map per storey (storeys.h). Same input, same
// bytes.

#include "core/image/rgb8_canvas.h"
#include "core/scene/probe.h"
#include "geometry/survey/survey_result.h"

#include <array>
#include <filesystem>
#include <span>
#include <vector>

namespace probeproxy {

// The scale's bin edges in degrees: bin k holds [edge k, edge k+1), the last one edge 7 and up.
inline constexpr std::array<double, 8> kSurveyScaleDeg = {0.0, 0.25, 1.0,  2.5,
                                                          5.0, 10.0, 20.0, 45.0};

// The colour of an error on the fixed scale.
std::array<std::uint8_t, 3> surveyErrorColour(double errorDeg);

struct SurveyMapOptions {
  bool probeNames = false;  // each capture point labelled with its probe's name
};

// The map of one storey (0 = lowest) of `storeyCount`, `storeyOf[i]` the storey of cell i.
// At least 800 pixels wide.
Rgb8Canvas renderSurveyMap(const SurveyResult& result, std::span<const Probe> probes,
                           std::span<const int> storeyOf, int storey, int storeyCount,
                           const SurveyMapOptions& options = {});

// Writes `outFolder`/<scene>_survey.png, or <scene>_survey_storey<k>.png (k from 1) for each
// storey when there are several; returns the files written.
std::vector<std::filesystem::path> writeSurveyMaps(const SurveyResult& result,
                                                   std::span<const Probe> probes,
                                                   const std::filesystem::path& outFolder,
                                                   const SurveyMapOptions& options = {});

}  // namespace probeproxy
