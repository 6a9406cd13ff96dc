// Catch2 for translation units that also see LibTorch: LibTorch's headers bring glog, whose CHECK
// macro (a fatal assertion) would silently replace Catch's CHECK. Include this instead of
// <catch2/catch.hpp>, before anything else: LibTorch first, glog's CHECK dropped, then Catch.
#pragma once

#include <torch/torch.h>

#ifdef CHECK
#undef CHECK
#endif

#include <catch2/catch.hpp>
