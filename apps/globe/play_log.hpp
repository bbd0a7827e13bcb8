// What `globe play` records per frame and how it is written: log.csv (deterministic: fixed
// precision, no timings), timing.csv (wall clock) and the summary.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "camera/camera_pose.hpp"
#include "collision/collision_response.hpp"

namespace globe::app {

struct FrameTimings {
  double selectMs = 0;     // scene updates: selection, mesh building, uploads
  double loadMs = 0;       // waiting for tile loads
  double collisionMs = 0;  // the camera controller (QOTCD + response)
  double drawMs = 0;       // draw and read-back
  double writeMs = 0;      // PNG encoding and writing
  double totalMs = 0;
};

enum class TerrainSource { Drawn, Nadir, Finest };
std::string_view toString(TerrainSource source);  // drawn | nadir | finest

struct FrameRecord {
  int frame = 0;
  double timeSeconds = 0;
  camera::CameraPose pose;          // after the controller: what is drawn
  double scriptedHeightMeters = 0;  // the path's height at this time
  // The exact surface under the camera of the tile the controller's array holds there (drawn, or
  // only added for collision where the nadir is out of view); where the array holds none, the
  // finest pyramid tile's. terrainSource says which.
  double terrainHeightMeters = 0;
  TerrainSource terrainSource = TerrainSource::Finest;
  double clearanceMeters = 0;      // pose height - terrain height
  double nearClearanceMeters = 0;  // the lowest near-plane corner above the drawn surface
  bool collided = false;           // any response this frame
  collision::Response response = collision::Response::None;
  // How far the controller lifted the camera this frame because the drawn ground changed under it
  // (the view made for the new pose drew finer or newly arrived tiles higher than the ground the
  // move was checked against there): the lift a viewer shows as a pop unless it is spread. Not
  // counted where that array held no ground under the camera (it moved out of the last view).
  double newGroundLiftMeters = 0;
  size_t missingTiles = 0;  // tiles the frame's view wanted whose load failed (drawn coarser)
  size_t tilesDrawn = 0;
  uint64_t imageryTextureBytes = 0;  // imagery textures on the GPU after the frame's draw
  double fovYDegrees = 0;            // the vertical field of view drawn
  FrameTimings timings;
};

// frame,time_s,lon_deg,lat_deg,height_m,terrain_height_m,clearance_m,collided,response,
// tiles_drawn,terrain_source,heading_deg,pitch_deg,roll_deg,scripted_height_m,near_clearance_m,
// lift_m,vertical_jolt_m,new_ground_lift_m,fov_deg (terrain_source: drawn | nadir | finest; lift_m =
// height_m - scripted_height_m; vertical_jolt_m: verticalJoltMeters; new_ground_lift_m:
// FrameRecord::newGroundLiftMeters)
std::string formatPlayLog(const std::vector<FrameRecord>& frames);
// frame,select_ms,load_ms,collision_ms,draw_ms,write_ms,total_ms
std::string formatTimingLog(const std::vector<FrameRecord>& frames);

struct PlaySummary {
  int frames = 0;
  int collisionFrames = 0;
  int firstCollisionFrame = -1;
  double minimumClearanceMeters = 0;
  int minimumClearanceFrame = -1;
  double medianFrameMs = 0, p90FrameMs = 0, maximumFrameMs = 0;
  double medianSelectMs = 0, medianLoadMs = 0, medianDrawMs = 0;
  uint64_t peakImageryTextureBytes = 0;
  uint64_t imageryTextureBudgetBytes = 0;  // set by the player; 0: no imagery layers
};
PlaySummary summarize(const std::vector<FrameRecord>& frames);

// How smoothly the camera moved: the vertical jolt of frame i is the second difference of the
// camera's height, h[i+1] - 2 h[i] + h[i-1] (m per frame², 0 at the ends). Frames where the
// response acts are those whose height differs from the script's (by > 1 cm) or that collided,
// with their neighbours; the ground's own jolt is the same difference of the terrain height under
// the camera over those frames.
struct MotionQuality {
  int responseFrames = 0;
  double p95JoltResponseMeters = 0;  // |jolt| over the frames where the response acts
  double p95GroundJoltMeters = 0;    // |the terrain's second difference| over the same frames
  double p95JoltFreeMeters = 0;      // |jolt| over the other frames (free flight)
  double minimumNearClearanceMeters = 0;
  // The largest newGroundLiftMeters of a frame: a pop, where finer ground arrived under the camera.
  double largestNewGroundLiftMeters = 0;
};
std::vector<double> verticalJoltMeters(const std::vector<FrameRecord>& frames);
MotionQuality motionQuality(const std::vector<FrameRecord>& frames);
std::string formatSummary(const PlaySummary& summary, const std::vector<FrameRecord>& frames);

// The q-quantile (0..1, nearest rank) of the values; 0 for none.
double quantile(std::vector<double> values, double q);

}  // namespace globe::app
