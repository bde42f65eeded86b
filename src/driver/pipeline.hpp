// The whole of skein on one page. Each stage is a free function of the stage folder named
// beside it; compile_model() runs them in order with a check between them.
//
//   read_stitch_mesh        mesh/obj_format      .obj text        -> StitchMesh
//   build_project           labeling             .yaml + coarse .obj -> StitchMesh (labeling, §3.4)
//   validate                mesh/stitch_mesh     StitchMesh       -> (throws MeshError)
//   place_shift_paths       transforms           StitchMesh       -> marks on every round (§3.1)
//   build_knit_graph        knitgraph/from_mesh  StitchMesh       -> KnitGraph
//   make_mismatches_knittable transforms         KnitGraph        -> joins/splits extruded (§3.2)
//   read_autoknit_st        mesh/autoknit_st     .st text         -> KnitGraph
//   correct_corner_links    transforms           KnitGraph        -> links as a knitter works them
//   check_consistency       knitgraph            KnitGraph        -> (asserts)
//   find_yarn_pieces        knitgraph            KnitGraph        -> YarnPieces      (§4.2)
//   build_dependency_graph  depgraph             KnitGraph        -> DependencyGraph (§4.1)
//   check_knittability      depgraph             DependencyGraph  -> Knittability (cycle)
//   schedule_stitches       schedule             all of the above -> Schedule (Algorithm 1)
//   lower_to_program        lowering             KnitGraph + Schedule -> Program (live loops)
//   Target::emit            targets/<name>       Compilation      -> output file
//   Simulator::verify       targets/<name>       output file      -> VerifyReport
//
// Run on request (skein yarn), not by compile_model:
//   build_yarn              yarn                 KnitGraph + mesh or .st positions -> YarnModel
//                                                (mesh relaxation §3.4, templates, relaxation §5)
#pragma once

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "depgraph/dependency_graph.hpp"
#include "knitgraph/knit_graph.hpp"
#include "knitgraph/yarn_pieces.hpp"
#include "labeling/project.hpp"
#include "lowering/program.hpp"
#include "mesh/stitch_mesh.hpp"
#include "schedule/schedule.hpp"
#include "transforms/shift_paths.hpp"

namespace skein {

struct Compilation {
  std::string input;
  std::optional<StitchMesh> mesh;  // absent for stitch graphs (.st); with its shift-paths
  ShiftPathSummary shift_paths;
  KnitGraph knit;
  YarnPieces yarns;
  DependencyGraph deps;
  Knittability knittability;
  Schedule schedule;  // empty unless knittable
  Program program;    // the live-loop program; empty unless knittable
  // The project's gauge, yarn and needle; absent for a stitch mesh or stitch graph file,
  // which does not say what size a stitch is.
  std::optional<YarnGauge> gauge;
};

// Called after each stage with its name and how long it took (for progress output).
using StageObserver = std::function<void(const char* stage, std::chrono::duration<double>)>;

// Reads INPUT (.obj stitch mesh or .st stitch graph) and runs every stage up to the schedule.
// Throws Error subclasses on bad input; an unknittable model is not an error (see
// knittability).
Compilation compile_model(const std::string& input, const StageObserver& observe = {});

// The same stages from a mesh or stitch graph already in memory (`name` is used in messages).
Compilation compile_stitch_mesh(StitchMesh mesh, const std::string& name,
                                const StageObserver& observe = {});
Compilation compile_knit_graph(KnitGraph graph, const std::string& name,
                               const StageObserver& observe = {});

// The text `skein check` prints: counts, rows, yarn pieces, mismatches, and the cycle if any.
std::string check_report(const Compilation& compilation);

}  // namespace skein
