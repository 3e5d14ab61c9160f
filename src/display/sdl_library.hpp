#pragma once
// SDL2 and SDL2_ttf, opened with dlopen when the first window opens instead of linked: with
// what they pull in (sound servers, Wayland, X11, D-Bus: 50 shared libraries) they cost every
// convray process 13 ms of loading and constructors, though only +D and convray view ever
// open a window (docs/benchmarks.md, "Start-up in huge pages"). Only src/display includes it;
// its calls read sdl().SDL_CreateWindow(...), with SDL's own declarations and types.
#include <SDL.h>
#include <SDL_ttf.h>

namespace convray::display {

// Every SDL2 and SDL2_ttf function convray calls (TTF_GetError is SDL_GetError's macro).
#define CONVRAY_SDL_FUNCTIONS(X)                                                              \
  X(SDL_CreateRenderer) X(SDL_CreateTexture) X(SDL_CreateTextureFromSurface)                  \
  X(SDL_CreateWindow) X(SDL_DestroyRenderer) X(SDL_DestroyTexture) X(SDL_DestroyWindow)      \
  X(SDL_FreeSurface) X(SDL_GetCurrentVideoDriver) X(SDL_GetError) X(SDL_GetKeyName)          \
  X(SDL_GetMouseState) X(SDL_InitSubSystem) X(SDL_PollEvent) X(SDL_Quit)                     \
  X(SDL_QuitSubSystem) X(SDL_RenderClear) X(SDL_RenderCopy) X(SDL_RenderFillRect)            \
  X(SDL_RenderPresent) X(SDL_SetHint) X(SDL_SetRenderDrawBlendMode)                          \
  X(SDL_SetRenderDrawColor) X(SDL_SetWindowTitle) X(SDL_UpdateTexture)                       \
  X(SDL_WaitEventTimeout)
#define CONVRAY_TTF_FUNCTIONS(X)                                                              \
  X(TTF_CloseFont) X(TTF_FontLineSkip) X(TTF_GlyphMetrics) X(TTF_Init) X(TTF_OpenFont)       \
  X(TTF_Quit) X(TTF_RenderUTF8_Blended)

struct SdlLibrary {
#define CONVRAY_SDL_POINTER(name) decltype(&::name) name = nullptr;
  CONVRAY_SDL_FUNCTIONS(CONVRAY_SDL_POINTER)
  CONVRAY_TTF_FUNCTIONS(CONVRAY_SDL_POINTER)
#undef CONVRAY_SDL_POINTER
};

// The functions, both libraries opened on the first call (from any thread). Throws NoDisplay
// (sdl_window.hpp) naming the library and the loader's reason when one cannot be opened or
// lacks a function; every later call throws the same.
const SdlLibrary& sdl();
// Whether sdl() has opened the libraries: what closes windows asks before calling SDL.
bool sdl_loaded();

}  // namespace convray::display
