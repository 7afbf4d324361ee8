// What a ground-truth pixel shows (the w of the world target written by ocean_surface_aov.frag and
// mesh_aov.frag; engine/dataset/ground_truth.h turns it into the object_id and water_mask AOVs).
#ifndef LAGOON_SHARED_GROUND_TRUTH_H
#define LAGOON_SHARED_GROUND_TRUTH_H

#define LAGOON_GT_NONE 0u     // nothing: the sky (the targets' clear value)
#define LAGOON_GT_WATER 1u    // the water surface
#define LAGOON_GT_FLOOR 2u    // the sea floor (procedural or glTF)
#define LAGOON_GT_OBJECT0 3u  // scene object k (objects[], then vehicles[]) is LAGOON_GT_OBJECT0 + k

#endif
