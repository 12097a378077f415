// The consumer's program: renders a scene file on twinraster's CPU twin into a PNG.
#include "twinraster.hpp"

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: render_cpu SCENE.json OUT.png\n";
    return 2;
  }
  try {
    const twinraster::Scene scene = twinraster::LoadScene(argv[1]);
    const twinraster::DrawList list = twinraster::BuildDrawList(scene);
    const twinraster::Image image = twinraster::cpu::RenderOnCpu(list);
    twinraster::files::WritePng(argv[2], image);
    std::cout << argv[2] << ": " << image.width << "x" << image.height << "\n";
  } catch (const std::exception& e) {
    std::cerr << "render_cpu: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
