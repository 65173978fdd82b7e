// prism_example SCENE OUT.tif: renders a scene with the Prism core library at
// the size the scene asks for and writes the picture, as `prism render SCENE
// -o OUT.tif` does with its default settings. Exit 0 on success, 1 on failure.
#include "core/accel/accel.h"
#include "core/io/diagnostic.h"
#include "core/io/picture_writer.h"
#include "core/io/scene_loader.h"
#include "core/render/renderer.h"

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: prism_example SCENE OUT.tif\n";
    return 1;
  }
  try {
    const prism::Scene scene = prism::loadAnyScene(argv[1]);
    const auto accel = prism::makeAccel(scene, prism::AccelKind::Bvh);
    prism::RenderSettings settings;
    settings.width = scene.width;
    settings.height = scene.height;
    const prism::RenderResult result = prism::render(scene, *accel, settings);
    prism::writePicture(argv[2], result, /*floatRadiance=*/false);
  } catch (const prism::SceneError& error) {
    for (const prism::Diagnostic& d : error.diagnostics())
      std::cerr << d.format() << "\n";
    return 1;
  } catch (const std::exception& error) {
    std::cerr << "prism_example: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
