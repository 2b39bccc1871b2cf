#include <hullcook/runtime.h>

#include <cstdio>
#include <cstring>

int main() {
  const char* version = hullcook::runtime_version();
  std::printf("linked hullcook runtime %s\n", version);
  return std::strlen(version) > 0 ? 0 : 1;
}
