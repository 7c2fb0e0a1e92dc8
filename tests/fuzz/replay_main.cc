// The driver of a harness in a build without libFuzzer (g++, CI): runs the harness once on
// every file named, or on every file of every folder named (its seed corpus and the inputs of
// crashes found so far), and says how many it ran. A harness that crashes, trips a sanitizer
// or throws fails the test that runs this.

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const fs::path p(argv[i]);
    if (fs::is_directory(p)) {
      for (const auto& e : fs::directory_iterator(p))
        if (e.is_regular_file()) files.push_back(e.path());
    } else if (fs::is_regular_file(p)) {
      files.push_back(p);
    } else {
      std::cerr << argv[0] << ": no such file or folder: " << p << "\n";
      return 66;
    }
  }
  if (files.empty()) {
    std::cerr << argv[0] << ": no inputs (give corpus folders or files)\n";
    return 66;
  }
  for (const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  }
  std::cout << argv[0] << ": " << files.size() << " inputs ran\n";
  return 0;
}
