// The page's side of the CesiumJS checks: window.globeTest's functions, called from node with
// page.evaluate. Every camera is LON,LAT,HEIGHT (m above the ellipsoid),HEADING,PITCH,ROLL
// (degrees), as `globe snapshot --camera` takes it; the vertical field of view is globe's, 45°.
/* global Cesium */
'use strict';
Cesium.Ion.defaultAccessToken = '';
const GLOBE_FOV_Y = Cesium.Math.toRadians(45);

window.globeTest = {
  viewer: null,
  provider: null,

  // A viewer with nothing but the terrain: a uniform black background (no sky box, atmosphere,
  // sun, moon or fog) and an untextured white globe, so that the sky is exactly what is black.
  // requestRenderMode: draw a frame only when asked or when a tile arrives (the tests: software
  // WebGL drawing nonstop took a core from the suite's other tests); off for frame timing.
  async init({ terrainUrl, ellipsoid = false, requestRenderMode = false }) {
    this.provider = ellipsoid ? new Cesium.EllipsoidTerrainProvider()
      : await Cesium.CesiumTerrainProvider.fromUrl(terrainUrl, { requestVertexNormals: true,
        requestWaterMask: false, requestMetadata: false });
    const viewer = new Cesium.Viewer('viewer', {
      baseLayer: false, terrainProvider: this.provider, geocoder: false, baseLayerPicker: false,
      animation: false, timeline: false, homeButton: false, sceneModePicker: false,
      navigationHelpButton: false, fullscreenButton: false, infoBox: false,
      selectionIndicator: false, creditContainer: 'credits', skyBox: false, skyAtmosphere: false,
      requestRenderMode, maximumRenderTimeChange: Infinity, msaaSamples: 1, scene3DOnly: true,
    });
    const scene = viewer.scene;
    scene.backgroundColor = Cesium.Color.BLACK;
    if (scene.sun) scene.sun.show = false;
    if (scene.moon) scene.moon.show = false;
    scene.fog.enabled = false;
    scene.globe.showGroundAtmosphere = false;
    scene.globe.enableLighting = false;
    scene.globe.baseColor = Cesium.Color.WHITE;
    scene.globe.maximumScreenSpaceError = 2;
    scene.globe.preloadAncestors = true;
    scene.postProcessStages.fxaa.enabled = false;
    viewer.resolutionScale = 1;
    this.viewer = viewer;
    return { ready: true, maxLevel: this.maxLevel() };
  },

  // The same viewer over the bare ellipsoid (or back over the tree).
  async setTerrain({ terrainUrl, ellipsoid = false }) {
    this.provider = ellipsoid ? new Cesium.EllipsoidTerrainProvider()
      : await Cesium.CesiumTerrainProvider.fromUrl(terrainUrl, { requestVertexNormals: true });
    this.viewer.terrainProvider = this.provider;
  },

  // Renders a frame now and returns the canvas as a PNG data URL (read in the same task as the
  // render, so the drawing buffer is still there); nothing but the globe's canvas.
  capture() {
    const scene = this.viewer.scene;
    scene.requestRender();  // in requestRenderMode render() draws only what was asked for
    scene.render();
    return scene.canvas.toDataURL('image/png');
  },

  // Stops (or restarts) rendering between checks, so that an idle viewer leaves the CPU alone.
  setRendering(on) { this.viewer.useDefaultRenderLoop = on; },

  // For a picture rather than a mask: heights coloured by a ramp (green lowlands, brown slopes,
  // grey summit: like globe's hypsometric colours), the sky and its haze, hill-shading under a
  // morning sun where the tree has vertex normals.
  pictureStyle() {
    const { scene } = this.viewer;
    const ramp = document.createElement('canvas');
    ramp.width = 256;
    ramp.height = 1;
    const ctx = ramp.getContext('2d');
    const g = ctx.createLinearGradient(0, 0, 256, 0);
    [[0, '#5f8f45'], [0.12, '#8fae5d'], [0.28, '#c9b57c'], [0.5, '#9a6a45'], [0.75, '#7d5a4a'],
      [0.9, '#b8b0aa'], [1, '#f4f4f4']].forEach(([o, c]) => g.addColorStop(o, c));
    ctx.fillStyle = g;
    ctx.fillRect(0, 0, 256, 1);
    scene.globe.material = Cesium.Material.fromType('ElevationRamp', {
      image: ramp.toDataURL(), minimumHeight: 0, maximumHeight: 3800 });
    scene.skyAtmosphere = new Cesium.SkyAtmosphere();
    scene.skyAtmosphere.show = true;
    scene.fog.enabled = true;
    scene.globe.showGroundAtmosphere = true;
    if (this.provider.hasVertexNormals) {
      this.viewer.clock.shouldAnimate = false;
      this.viewer.clock.currentTime = Cesium.JulianDate.fromIso8601('2024-05-01T01:30:00Z');
      scene.globe.enableLighting = true;
    }
  },

  // Back to the mask: a black sky, an untextured white globe, no lighting.
  maskStyle() {
    const { scene } = this.viewer;
    scene.globe.material = undefined;
    scene.skyAtmosphere.show = false;
    scene.fog.enabled = false;
    scene.globe.showGroundAtmosphere = false;
    scene.globe.enableLighting = false;
  },

  maxLevel() {
    const a = this.provider.availability;
    return a ? a._maximumLevel : 0;  // TileAvailability keeps it without a getter
  },

  // sampleTerrainMostDetailed at [lon, lat] degrees: [height, level of the tile sampled].
  async sample(points) {
    const carto = points.map(([lon, lat]) => Cesium.Cartographic.fromDegrees(lon, lat));
    const levels = carto.map((c) =>
      this.provider.availability.computeMaximumLevelAtPosition(c));
    const sampled = await Cesium.sampleTerrainMostDetailed(this.provider, carto, true);
    return sampled.map((c, i) => [c.height, levels[i]]);
  },

  setCamera([lon, lat, height, heading = 0, pitch = -90, roll = 0]) {
    const { scene, camera } = this.viewer;
    const canvas = scene.canvas;
    const aspect = canvas.clientWidth / canvas.clientHeight;
    // Cesium's fov is the horizontal one where the canvas is wider than tall.
    camera.frustum.fov = aspect > 1 ? 2 * Math.atan(Math.tan(GLOBE_FOV_Y / 2) * aspect) : GLOBE_FOV_Y;
    camera.frustum.near = 1;
    camera.setView({
      destination: Cesium.Cartesian3.fromDegrees(lon, lat, height),
      orientation: { heading: Cesium.Math.toRadians(heading), pitch: Cesium.Math.toRadians(pitch),
        roll: Cesium.Math.toRadians(roll) },
    });
  },

  // Resolves once the globe has loaded every tile the view needs (tilesLoaded on `frames`
  // successive frames), or rejects after timeoutMs.
  // In requestRenderMode a frame is asked for every 50 ms while waiting (tiles are requested
  // while a frame is drawn).
  waitTilesLoaded(timeoutMs = 90000, frames = 10) {
    const scene = this.viewer.scene;
    return new Promise((resolve, reject) => {
      let good = 0;
      const started = performance.now();
      const ticks = scene.requestRenderMode ? setInterval(() => scene.requestRender(), 50) : null;
      const remove = scene.postRender.addEventListener(() => {
        good = scene.globe.tilesLoaded ? good + 1 : 0;
        const late = performance.now() - started > timeoutMs;
        if (good < frames && !late) return;
        remove();
        clearInterval(ticks);
        if (good >= frames) resolve(performance.now() - started);
        else reject(new Error(`tiles not loaded after ${timeoutMs} ms`));
      });
      scene.requestRender();
    });
  },

  // Triangles of the terrain tiles drawn in the last frame (their meshes' index counts / 3), and
  // the number of tiles.
  terrainTriangles() {
    const surface = this.viewer.scene.globe._surface;
    let triangles = 0;
    for (const tile of surface._tilesToRender) {
      const mesh = tile.data && (tile.data.renderedMesh || tile.data.mesh);
      if (mesh && mesh.indices) triangles += mesh.indices.length / 3;
    }
    return { tiles: surface._tilesToRender.length, triangles };
  },

  // Frame times over n frames, rendered back to back (requestRenderMode off): the intervals
  // between successive postRender events, and the time from preRender to the frame drawn, in ms.
  // Each frame ends with a 1-pixel readPixels, which waits until GL has drawn it (ANGLE's GPU
  // process would otherwise draw in parallel with the next frame's JavaScript, unmeasured).
  frameTimes(n) {
    const scene = this.viewer.scene;
    const gl = scene.context._gl;
    const pixel = new Uint8Array(4);
    return new Promise((resolve) => {
      const intervals = [];
      const renders = [];
      let last = null;
      let preAt = null;
      const removePre = scene.preRender.addEventListener(() => { preAt = performance.now(); });
      const remove = scene.postRender.addEventListener(() => {
        gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
        const now = performance.now();
        if (preAt !== null) renders.push(now - preAt);
        if (last !== null) intervals.push(now - last);
        last = now;
        if (intervals.length >= n) {
          remove();
          removePre();
          resolve({ intervals, renders });
        }
      });
    });
  },
};
