// A GLFW window with a GL 3.3 core context (24-bit depth, double-buffered) for the viewer.
#pragma once

#include <memory>
#include <string>

#include "core/result.hpp"

struct GLFWwindow;

namespace globe::render {

struct GlfwWindowOptions {
  int widthPixels = 1280;
  int heightPixels = 720;
  std::string title = "globe";
  bool visible = true;
  bool vsync = true;
};

class GlfwWindowContext {
 public:
  // Initialises GLFW (reference-counted across windows), opens the window, makes its context
  // current, loads the GL functions and does the warm-up draw. Fails cleanly without a display.
  static Result<std::unique_ptr<GlfwWindowContext>> create(const GlfwWindowOptions& options);
  ~GlfwWindowContext();
  GlfwWindowContext(const GlfwWindowContext&) = delete;
  GlfwWindowContext& operator=(const GlfwWindowContext&) = delete;

  Result<void> makeCurrent();
  void swapBuffers();
  void pollEvents();
  bool shouldClose() const;
  void requestClose();
  // The framebuffer size in pixels (may differ from the window size on high-DPI screens).
  int framebufferWidthPixels() const;
  int framebufferHeightPixels() const;
  // For input callbacks and the like; the window stays owned by this object.
  GLFWwindow* window() const { return window_; }

 private:
  explicit GlfwWindowContext(GLFWwindow* window) : window_(window) {}
  GLFWwindow* window_;
};

}  // namespace globe::render
