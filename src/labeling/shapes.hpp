// Parametric coarse meshes and their project files, so users need not model everyday shapes
// (`skein new tube --circumference 40cm --length 20cm`). Sizes are in centimetres; the mesh
// is in centimetres too, with y up and knitting starting at the lowest boundary (y = 0).
#pragma once

#include <string>
#include <vector>

#include "labeling/coarse_mesh.hpp"

namespace skein {

struct ShapeSize {
  double circumference = 0;  // tube, hat, sock (leg), sweater (chest), mitten (hand), shorts and
                             // trousers (hip); 0: the kind's default
  double width = 0;          // sheet
  double length = 0;         // every kind: tube or sheet length, hat or sock or body height
};

struct Shape {
  CoarseMesh mesh;
  std::string project;  // the project file's text; it names the mesh as NAME.obj
};

// Kinds: shape_kinds(). Throws UsageError for an unknown kind or bad size.
Shape make_shape(const std::string& kind, const ShapeSize& size, const std::string& name);
std::vector<std::string> shape_kinds();

// Lengths `skein new` accepts (docs/formats.md, "Limits").
inline constexpr double kMinLengthCm = 1, kMaxLengthCm = 1000;

// "40cm", "400mm", "15.7in", "1.2m" -> centimetres; throws UsageError for a length without
// its unit, not finite or outside [kMinLengthCm, kMaxLengthCm].
double parse_length_cm(const std::string& text);

// Writes NAME.obj and NAME.yaml beside each other (atomically); returns the project's path.
std::string write_shape(const Shape& shape, const std::string& path_without_extension);

}  // namespace skein
