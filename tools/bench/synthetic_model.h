// Full-size synthetic models for benchmarks: SMPL-sized (6890 vertices, 24
// joints, 207 correctives) and SMPL-X-sized (10475 vertices, 55 joints, 486
// correctives, 300 + 100 shape/expression directions). Not bodies: random
// clouds with the licensed models' array shapes, skin weights falling off
// from each joint, and correctives concentrated on the vertices a joint and
// its parent move (as learned posedirs are), plus a small global noise floor.
#pragma once

#include "core/body_model.h"

namespace smpl {

BodyModel syntheticModel(ModelKind kind, int num_vertices, int num_betas, int num_expressions,
                         uint64_t seed);

}  // namespace smpl
