// GLFW window + context; GLFW's errors are collected into the Result messages.
#define GLFW_INCLUDE_NONE
#include "render/glfw_window_context.hpp"

#include <GLFW/glfw3.h>

#include <mutex>
#include <string>

#include "render/gl_loader.hpp"
#include "render/gl_warm_up.hpp"

namespace globe::render {
namespace {

std::mutex glfwMutex;
int glfwUsers = 0;  // windows alive; GLFW is terminated when the last one goes
thread_local std::string lastGlfwError;

void recordGlfwError(int code, const char* description) {
  lastGlfwError = "GLFW error " + std::to_string(code) + ": " + (description ? description : "");
}

Result<void> acquireGlfw() {
  std::lock_guard lock(glfwMutex);
  if (glfwUsers == 0) {
    glfwSetErrorCallback(recordGlfwError);
    lastGlfwError.clear();
    if (glfwInit() != GLFW_TRUE) return makeError("GLFW: glfwInit failed: " + lastGlfwError);
  }
  ++glfwUsers;
  return {};
}

void releaseGlfw() {
  std::lock_guard lock(glfwMutex);
  if (--glfwUsers == 0) glfwTerminate();
}

}  // namespace

Result<std::unique_ptr<GlfwWindowContext>> GlfwWindowContext::create(
    const GlfwWindowOptions& options) {
  if (options.widthPixels < 1 || options.heightPixels < 1) {
    return makeError("GLFW: window size " + std::to_string(options.widthPixels) + "x" +
                     std::to_string(options.heightPixels) + " out of range");
  }
  if (auto acquired = acquireGlfw(); !acquired) return makeError(acquired.error());
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_RED_BITS, 8);
  glfwWindowHint(GLFW_GREEN_BITS, 8);
  glfwWindowHint(GLFW_BLUE_BITS, 8);
  glfwWindowHint(GLFW_DEPTH_BITS, 24);
  glfwWindowHint(GLFW_DOUBLEBUFFER, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, options.visible ? GLFW_TRUE : GLFW_FALSE);
  lastGlfwError.clear();
  GLFWwindow* window = glfwCreateWindow(options.widthPixels, options.heightPixels,
                                        options.title.c_str(), nullptr, nullptr);
  if (window == nullptr) {
    releaseGlfw();
    return makeError("GLFW: cannot open a " + std::to_string(options.widthPixels) + "x" +
                     std::to_string(options.heightPixels) +
                     " window with a 3.3 core context: " + lastGlfwError);
  }
  std::unique_ptr<GlfwWindowContext> context(new GlfwWindowContext(window));
  if (auto current = context->makeCurrent(); !current) return makeError(current.error());
  glfwSwapInterval(options.vsync ? 1 : 0);
  if (auto warm = warmUpGl(); !warm) return makeError(warm.error());
  return context;
}

GlfwWindowContext::~GlfwWindowContext() {
  if (glfwGetCurrentContext() == window_) glfwMakeContextCurrent(nullptr);
  glfwDestroyWindow(window_);
  releaseGlfw();
}

Result<void> GlfwWindowContext::makeCurrent() {
  glfwMakeContextCurrent(window_);
  return loadGlFunctions(glfwGetProcAddress);
}

void GlfwWindowContext::swapBuffers() { glfwSwapBuffers(window_); }
void GlfwWindowContext::pollEvents() { glfwPollEvents(); }
bool GlfwWindowContext::shouldClose() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
void GlfwWindowContext::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

int GlfwWindowContext::framebufferWidthPixels() const {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  return width;
}

int GlfwWindowContext::framebufferHeightPixels() const {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  return height;
}

}  // namespace globe::render
