// Libraries loaded on first use (dlopen), so that a process pays only for what it uses: LibTorch
// (the learned-policy runtime, libautoblock_learn.so) and Qt (PNG pictures, libautoblock_raster.so)
// cost a command that needs neither nothing.
#pragma once

#include <string>

namespace autoblock {

// Inputs:  library, a file name such as "libautoblock_learn.so"; symbol, an exported C name;
//          env, an environment variable that may give the library's full path instead.
// Outputs: the symbol's address. The library is looked for in $env when set, else in the folder
//          libautoblock_core.so was loaded from (build/lib; an installed lib folder), and is loaded
//          once and never unloaded. A symbol already in the process (a library linked in, as in its
//          own tests) is used as it is. Throws std::runtime_error naming the library and the
//          loader's message when it cannot be loaded.
void* plugin_symbol(const std::string& library, const char* symbol, const char* env);

// True when symbol is already in the process (loaded or linked), without loading anything.
bool plugin_symbol_loaded(const char* symbol);

}  // namespace autoblock
