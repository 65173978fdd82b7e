// The 8-bit TIFF and PNG that Prism writes itself (core/io/tiff_writer.cpp,
// png_writer.cpp): read back by OpenImageIO pixel for pixel with their texts,
// compared byte for byte with the file OpenImageIO writes for the same
// picture, and the executable checked to carry no OpenImageIO.
#include "core/io/image_io.h"
#include "core/io/oiio_module.h"

#include "test_files.h"
#include "test_pictures.h"

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <map>
#include <memory>

namespace prism {
namespace {

using std::filesystem::path;

// A picture with every byte value in each channel and no two rows alike, not
// a multiple of the 32-row strip in height, so the last strip is short.
std::vector<std::uint8_t> testPattern(int width, int height) {
  std::vector<std::uint8_t> rgb(std::size_t(width) * std::size_t(height) * 3);
  for (std::size_t i = 0; i < rgb.size(); ++i)
    rgb[i] = std::uint8_t((i * 7919u) ^ (i >> 5) ^ (i % 3 == 0 ? 0x55 : 0));
  return rgb;
}

// The file OpenImageIO writes for the picture, through the module's entry.
void writeWithOiio(const path& p, int width, int height, const std::vector<std::uint8_t>& rgb,
                   const std::string& description) {
  auto write = reinterpret_cast<PrismOiioWriteFn>(oiioModuleSymbol("prism_oiio_write"));
  char error[256] = "";
  ASSERT_EQ(write(p.c_str(), p.c_str(), width, height, 0, rgb.data(), description.c_str(), error,
                  sizeof error),
            1)
      << error;
}

class PictureFormats : public ::testing::TestWithParam<const char*> {};

TEST_P(PictureFormats, ReadBackExactlyWithTheirTexts) {
  const test::ScratchDir dir;
  const path file = dir.path() / (std::string("p") + GetParam());
  const int w = 37, h = 70;
  const std::vector<std::uint8_t> rgb = testPattern(w, h);
  writeImage8(file, w, h, rgb, "exposed by avgmax 0.5");
  auto in = OIIO::ImageInput::open(file.string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, w);
  EXPECT_EQ(in->spec().height, h);
  EXPECT_EQ(in->spec().nchannels, 3);
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::UINT8);
  EXPECT_EQ(in->spec().get_string_attribute("Software"), "Prism");
  EXPECT_EQ(in->spec().get_string_attribute("ImageDescription"), "exposed by avgmax 0.5");
  std::vector<std::uint8_t> back(rgb.size());
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, back.data()));
  EXPECT_EQ(back, rgb);
}

INSTANTIATE_TEST_SUITE_P(TiffAndPng, PictureFormats, ::testing::Values(".tif", ".png"),
                         [](const auto& param) { return std::string(param.param + 1); });

// The same picture written by Prism (DIR/ours.EXT) and by OpenImageIO
// (DIR/theirs.EXT).
void writeBoth(const test::ScratchDir& dir, const std::string& ext) {
  const int w = 37, h = 70;
  const std::vector<std::uint8_t> rgb = testPattern(w, h);
  writeImage8(dir / ("ours" + ext), w, h, rgb, "exposed by avgmax 0.5");
  writeWithOiio(dir / ("theirs" + ext), w, h, rgb, "exposed by avgmax 0.5");
}

TEST(PictureFormats, PngHasOpenImageIOsBytes) {
  const test::ScratchDir dir;
  writeBoth(dir, ".png");
  const std::string ours = test::slurp(dir / "ours.png");
  ASSERT_GT(ours.size(), 100u);
  EXPECT_TRUE(ours == test::slurp(dir / "theirs.png")) << "the files differ";
}

// Every tag OpenImageIO reads from the file (compression, predictor, rows per
// strip, orientation, texts...) the same as in the file it writes itself,
// but for the moment of writing.
TEST(PictureFormats, TiffHasOpenImageIOsTags) {
  const test::ScratchDir dir;
  writeBoth(dir, ".tif");
  const auto tags = [](const path& p) {
    auto in = OIIO::ImageInput::open(p.string());
    EXPECT_TRUE(in) << p;
    std::map<std::string, std::string> all;
    if (!in) return all;
    for (const OIIO::ParamValue& attr : in->spec().extra_attribs)
      if (attr.name() != "DateTime") all[attr.name().string()] = attr.get_string();
    return all;
  };
  const auto ours = tags(dir / "ours.tif");
  EXPECT_GE(ours.size(), 6u);
  EXPECT_EQ(ours.at("compression"), "zip");
  EXPECT_EQ(ours, tags(dir / "theirs.tif"));
}

TEST(PictureFormats, UnwritableDirectoryIsReportedAndLeavesNothing) {
  const test::ScratchDir dir;
  const path file = dir.path() / "missing" / "p.tif";
  try {
    writeImage8(file, 2, 2, std::vector<std::uint8_t>(12, 9));
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write '" + file.string() + "'"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(test::fs::exists(file));
}

// OpenImageIO and its ~260 libraries cost ~0.2 s and ~100 MB at every start;
// the executable must load them only through the module, when it needs them.
TEST(PictureFormats, ExecutableLinksNoOpenImageIO) {
  std::unique_ptr<FILE, int (*)(FILE*)> ldd(popen("ldd '" PRISM_BINARY "' 2>&1", "r"), pclose);
  ASSERT_TRUE(ldd);
  std::string listing;
  char line[512];
  int libraries = 0;
  while (std::fgets(line, sizeof line, ldd.get())) {
    listing += line;
    ++libraries;
  }
  EXPECT_GT(libraries, 3) << listing; // ldd ran and listed something
  EXPECT_EQ(listing.find("OpenImageIO"), std::string::npos) << listing;
  EXPECT_LT(libraries, 60) << listing;
}

} // namespace
} // namespace prism
