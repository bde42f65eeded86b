// Yarn-level relaxation (after Kaldor et al. 2008, as position-based steps): each step moves
// every point by the contact push of the segments within a yarn diameter of it (spatial hash
// with a Verlet skin, yarn/contacts), a bending pull towards the straight line through its
// neighbours and a weak anchor to where its template put it (which keeps the global shape),
// clamped to a quarter radius so no yarn can jump through another; then it projects the
// segment lengths back to their rest lengths (inextensible yarn, red-black Gauss-Seidel).
// Every part is linear in yarn length and split over threads with a fixed partition.
#pragma once

#include <functional>

#include "yarn/curves.hpp"

namespace skein {

struct RelaxProgress {
  int step;
  float max_move;  // in yarn radii, this step
  float overlap;   // deepest overlap of two yarns, in yarn diameters
};

struct RelaxOptions {
  int max_steps = 3000;
  float tolerance = 0.01f;  // stop when no point moves more than this many radii in a step
  float overlap = 0.1f;     // and no two yarns overlap by more than this many diameters
  float bend = 0.3f;        // pull towards the smooth curve through the neighbours
  float anchor = 0.002f;    // pull back towards the template, per step
  int length_sweeps = 4;
  unsigned threads = 0;                                // 0: all cores
  std::function<void(const RelaxProgress&)> progress;  // called every progress_every steps
  int progress_every = 100;
};

struct RelaxReport {
  int steps = 0;
  bool converged = false;
  float max_move = 0;   // in radii, the last step
  float overlap = 0;    // in diameters, the last step
  int pair_builds = 0;  // how often the list of close segment pairs was built
  double seconds = 0;
};

RelaxReport relax_yarn(YarnModel& model, const RelaxOptions& options = {});

}  // namespace skein
