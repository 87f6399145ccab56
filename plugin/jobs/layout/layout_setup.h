#pragma once
// What a layout job reads and resolves before it lays anything out: the scene or level, its
// ray caster, the layout's and the survey's options with the floor and player settled (the
// user's, else the scene's measured_with, else the level's game), and the seed points the floor
// is flood-filled from. The job and every process that shares its work (a Dask worker,
// plugin/jobs/layout/layout_worker.h) start from the same setup, so they walk the same floor.

#include "core/scene/scene.h"
#include "geometry/layout/layout_options.h"
#include "geometry/level/level_mesh.h"
#include "geometry/raycast/level_ray_caster.h"
#include "geometry/survey/survey_options.h"
#include "plugin/jobs/layout/layout_job.h"

#include <glm/vec3.hpp>

#include <memory>
#include <string>
#include <vector>

namespace probeproxy::jobs {

struct LayoutSetup {
  Scene input;
  bool inMemory = false;  // the scene came as LayoutJobOptions::input, not a file
  std::unique_ptr<LevelMesh> level;
  std::unique_ptr<LevelRayCaster> rayCaster;  // over *level
  LayoutOptions layout;
  SurveyOptions survey;
  std::vector<glm::dvec3> seedsMeters;
  std::string seededFrom;  // as LayoutJobResult::seededFrom
};

// Throws InputError for an input that cannot be laid out (as runLayoutJob).
LayoutSetup prepareLayout(const LayoutJobOptions& options);

}  // namespace probeproxy::jobs
