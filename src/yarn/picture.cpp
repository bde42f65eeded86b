#include "yarn/picture.hpp"

#include <png.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <ostream>

#include "common/error.hpp"
#include "yarn/contacts.hpp"
#include "yarn/parallel.hpp"

namespace skein {
namespace {

constexpr int kSupersample = 2;

// Yarn colours, one per piece in turn.
constexpr std::array<std::array<float, 3>, 8> kPalette{{{0.80f, 0.22f, 0.20f},
                                                        {0.20f, 0.45f, 0.75f},
                                                        {0.90f, 0.70f, 0.20f},
                                                        {0.30f, 0.62f, 0.35f},
                                                        {0.55f, 0.35f, 0.65f},
                                                        {0.92f, 0.50f, 0.20f},
                                                        {0.25f, 0.65f, 0.65f},
                                                        {0.85f, 0.45f, 0.60f}}};

struct Camera {
  Point3 right, up, towards;                        // towards the viewer
  float scale = 1;                                  // pixels per model unit
  float left = 0, top = 0;                          // model coordinates of the picture's corner
  Eigen::Vector3f project(const Point3& p) const {  // pixel x, pixel y (down), depth
    return {(p.dot(right) - left) * scale, (top - p.dot(up)) * scale, p.dot(towards)};
  }
};

Camera camera_for(const YarnModel& model, int width, int height, const PictureOptions& o) {
  const float az = o.azimuth * std::numbers::pi_v<float> / 180;
  const float el = o.elevation * std::numbers::pi_v<float> / 180;
  Camera c;
  c.towards = Point3(std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az));
  c.right = Point3::UnitY().cross(c.towards).normalized();
  c.up = c.towards.cross(c.right);
  float x0 = std::numeric_limits<float>::max(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const Point3& p : model.point) {
    x0 = std::min(x0, p.dot(c.right)), x1 = std::max(x1, p.dot(c.right));
    y0 = std::min(y0, p.dot(c.up)), y1 = std::max(y1, p.dot(c.up));
  }
  const float margin = 0.04f;
  float w = std::max(x1 - x0, 1e-6f) + 2 * model.radius,
        h = std::max(y1 - y0, 1e-6f) + 2 * model.radius;
  c.scale = std::min(width / w, height / h) * (1 - 2 * margin);
  c.left = (x0 + x1) / 2 - width / c.scale / 2;
  c.top = (y0 + y1) / 2 + height / c.scale / 2;
  return c;
}

struct Canvas {
  int width, height;
  std::vector<float> depth;
  std::vector<std::array<float, 3>> colour;
};

// Draws the capsule of one segment into the rows [row0, row1) of the canvas.
void draw_capsule(Canvas& canvas, const Eigen::Vector3f& a, const Eigen::Vector3f& b, float radius,
                  float depth_per_pixel, const std::array<float, 3>& rgb, int row0, int row1) {
  const int x0 = std::max(0, static_cast<int>(std::floor(std::min(a.x(), b.x()) - radius)));
  const int x1 =
      std::min(canvas.width - 1, static_cast<int>(std::ceil(std::max(a.x(), b.x()) + radius)));
  const int y0 = std::max(row0, static_cast<int>(std::floor(std::min(a.y(), b.y()) - radius)));
  const int y1 = std::min(row1 - 1, static_cast<int>(std::ceil(std::max(a.y(), b.y()) + radius)));
  const Eigen::Vector2f d(b.x() - a.x(), b.y() - a.y());
  const float dd = std::max(d.squaredNorm(), 1e-12f);
  const Eigen::Vector3f light = Eigen::Vector3f(-0.45f, -0.55f, 0.70f).normalized();
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      Eigen::Vector2f p(x + 0.5f - a.x(), y + 0.5f - a.y());
      float t = std::clamp(p.dot(d) / dd, 0.0f, 1.0f);
      Eigen::Vector2f off = p - t * d;
      float r2 = off.squaredNorm();
      if (r2 >= radius * radius) continue;
      float bulge = std::sqrt(radius * radius - r2);
      float z = a.z() + t * (b.z() - a.z()) + bulge * depth_per_pixel;
      std::size_t at = static_cast<std::size_t>(y) * canvas.width + x;
      if (z <= canvas.depth[at]) continue;
      canvas.depth[at] = z;
      Eigen::Vector3f n(off.x() / radius, off.y() / radius, bulge / radius);
      float diffuse = std::max(0.0f, n.dot(light));
      float shine =
          std::pow(std::max(0.0f, n.dot((light + Eigen::Vector3f::UnitZ()).normalized())), 24.0f);
      float shade = 0.28f + 0.72f * diffuse;
      for (int k = 0; k < 3; ++k)
        canvas.colour[at][k] = std::min(1.0f, rgb[k] * shade + 0.18f * shine);
    }
}

Canvas rasterise(const YarnModel& model, const Camera& camera, int width, int height,
                 unsigned threads) {
  Canvas c{width,
           height,
           std::vector<float>(static_cast<std::size_t>(width) * height,
                              -std::numeric_limits<float>::infinity()),
           {}};
  c.colour.resize(c.depth.size());
  for (int y = 0; y < height; ++y)  // a soft background, lighter at the top
    for (int x = 0; x < width; ++x) {
      float v = 0.96f - 0.10f * static_cast<float>(y) / static_cast<float>(height);
      c.colour[static_cast<std::size_t>(y) * width + x] = {v, v * 0.98f, v * 0.95f};
    }
  std::vector<Eigen::Vector3f> screen(model.point.size());
  for (std::size_t i = 0; i < screen.size(); ++i) screen[i] = camera.project(model.point[i]);
  std::vector<std::uint8_t> starts = segment_starts(model.point.size(), model.piece_first);
  std::vector<std::uint32_t> piece_of(model.point.size());
  for (std::uint32_t p = 0; p < model.pieces(); ++p)
    std::fill(piece_of.begin() + model.piece_first[p], piece_of.begin() + model.piece_first[p + 1],
              p);
  const float radius = model.radius * camera.scale;
  const float depth_per_pixel = 1 / camera.scale;
  unsigned bands = std::max(1u, threads);
  parallel_for(static_cast<std::size_t>(bands) * 1024, bands,
               [&](std::size_t, std::size_t, unsigned band) {
                 int row0 = height * static_cast<int>(band) / static_cast<int>(bands);
                 int row1 = height * static_cast<int>(band + 1) / static_cast<int>(bands);
                 for (std::size_t i = 0; i + 1 < screen.size(); ++i)
                   if (starts[i])
                     draw_capsule(c, screen[i], screen[i + 1], radius, depth_per_pixel,
                                  kPalette[piece_of[i] % kPalette.size()], row0, row1);
               });
  return c;
}

void write_png(std::ostream& out, int width, int height, const std::vector<std::uint8_t>& rgb) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    throw IoError("libpng could not start a picture");
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw IoError("libpng failed to write the picture");
  }
  png_set_write_fn(
      png, &out,
      [](png_structp p, png_bytep data, png_size_t size) {
        static_cast<std::ostream*>(png_get_io_ptr(p))
            ->write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
      },
      nullptr);
  png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y)
    png_write_row(png, rgb.data() + static_cast<std::size_t>(y) * width * 3);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
}

}  // namespace

void write_yarn_png(const YarnModel& model, std::ostream& out, const PictureOptions& options) {
  const int w = options.width * kSupersample, h = options.height * kSupersample;
  Camera camera = camera_for(model, w, h, options);
  Canvas c = rasterise(model, camera, w, h, options.threads ? options.threads : default_threads());
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(options.width) * options.height * 3);
  for (int y = 0; y < options.height; ++y)
    for (int x = 0; x < options.width; ++x)
      for (int k = 0; k < 3; ++k) {
        float sum = 0;
        for (int sy = 0; sy < kSupersample; ++sy)
          for (int sx = 0; sx < kSupersample; ++sx)
            sum += c.colour[static_cast<std::size_t>(y * kSupersample + sy) * w + x * kSupersample +
                            sx][k];
        float v = sum / (kSupersample * kSupersample);
        rgb[(static_cast<std::size_t>(y) * options.width + x) * 3 + k] =
            static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255));
      }
  write_png(out, options.width, options.height, rgb);
}

}  // namespace skein
