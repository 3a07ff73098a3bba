// 02_user_image: an image type of the user's own, adapted member style. A class that already has
// width(), height(), read(x, y) and write(x, y, p) models tessera::WritableImage as it is; its pixel
// struct needs one pixel_traits specialization. Then every tessera function accepts it.
// Usage: example_02_user_image [OUTPUT_DIR]   (writes 02_user_image.png and 02_user_image_grey.png)
#include <tessera/core/explain.hpp>
#include <tessera/core/image.hpp>
#include <tessera/core/image_buffer.hpp>
#include <tessera/image/exemplars.hpp>
#include <tessera/io/png.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

// [snippet:member-image]
// The application's own colour and bitmap types.
struct Color {
  std::uint8_t r = 0, g = 0, b = 0;
};

class Bitmap {
 public:
  Bitmap(int width, int height) : width_(width), height_(height), pixels_(std::size_t(width) * std::size_t(height)) {}
  int width() const { return width_; }
  int height() const { return height_; }
  Color read(std::ptrdiff_t x, std::ptrdiff_t y) const { return pixels_[index(x, y)]; }
  void write(std::ptrdiff_t x, std::ptrdiff_t y, const Color& c) { pixels_[index(x, y)] = c; }

 private:
  std::size_t index(std::ptrdiff_t x, std::ptrdiff_t y) const { return std::size_t(y * width_ + x); }
  int width_, height_;
  std::vector<Color> pixels_;
};

// Tell tessera what a Color is: three uint8 channels.
template <>
struct tessera::pixel_traits<Color> {
  using channel_type = std::uint8_t;
  static constexpr int channels = 3;
  static std::uint8_t get(const Color& c, int i) { return i == 0 ? c.r : i == 1 ? c.g : c.b; }
  static void set(Color& c, int i, std::uint8_t v) { (i == 0 ? c.r : i == 1 ? c.g : c.b) = v; }
};

static_assert(tessera::WritableImage<Bitmap>);  // or tessera::explain_writable_image<Bitmap>() for the reason
// [/snippet]

int fail(const tessera::status& s) {
  std::fprintf(stderr, "error: %s\n", s.to_string().c_str());
  return 1;
}

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  tessera::explain_writable_image<Bitmap>();  // compiles to nothing when Bitmap fits

  // [snippet:member-image-use]
  Bitmap bitmap(128, 96);
  auto weave = tessera::make_exemplar<std::uint8_t, 3>(tessera::exemplar_kind::weave, {.width = 128, .height = 96});
  if (!weave) return fail(weave.error());
  if (auto s = tessera::copy_image(*weave, bitmap); !s) return fail(s);  // tessera writes into Bitmap

  // The application edits its bitmap its own way (a warm tint) ...
  for (int y = 0; y < bitmap.height(); ++y)
    for (int x = 0; x < bitmap.width(); ++x) {
      Color c = bitmap.read(x, y);
      c.r = static_cast<std::uint8_t>(std::min(255, c.r + 40));
      bitmap.write(x, y, c);
    }
  // ... and tessera reads it back: a float grey copy, and PNG files straight from the Bitmap.
  auto grey = tessera::to_buffer<float, 1>(bitmap);
  if (!grey) return fail(grey.error());
  // [/snippet]
  double mean = 0;
  for (std::ptrdiff_t y = 0; y < grey->height(); ++y)
    for (std::ptrdiff_t x = 0; x < grey->width(); ++x) mean += grey->read(x, y)[0];
  mean /= static_cast<double>(grey->width() * grey->height());

  const std::string colour_path = dir + "/02_user_image.png", grey_path = dir + "/02_user_image_grey.png";
  if (auto s = tessera::write_png(colour_path, bitmap); !s) return fail(s);
  if (auto s = tessera::write_png(grey_path, *grey); !s) return fail(s);
  std::printf("Bitmap %d x %d, mean grey %.3f\nwrote %s\nwrote %s\n", bitmap.width(), bitmap.height(), mean,
              colour_path.c_str(), grey_path.c_str());
  return 0;
}
