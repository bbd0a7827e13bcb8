// The page's side of the MapLibre checks: window.globeTest's functions, called from node with
// page.evaluate once window.globeTestReady is set.
import * as maplibregl from '/maplibre/maplibre-gl.mjs';

window.globeTest = {
  map: null,

  // A map whose terrain is the tree ({z}/{x}/{y}.png, Terrarium, 256 px tiles, to maxzoom):
  // resolves on the first idle event (every tile the view needs loaded and drawn).
  init({ tiles, maxzoom, bounds, center, zoom, pitch = 0, bearing = 0, timeoutMs = 90000 }) {
    // The terrain and the layers drawn from heights read the tree as two sources (MapLibre's
    // advice: a source draped as terrain is sampled differently); the browser's cache serves
    // the second.
    const dem = { type: 'raster-dem', tiles: [location.origin + tiles], encoding: 'terrarium',
      tileSize: 256, maxzoom, bounds };
    const map = new maplibregl.Map({
      container: 'map', center, zoom, pitch, bearing, maxPitch: 85, attributionControl: false,
      canvasContextAttributes: { antialias: false, preserveDrawingBuffer: true },
      fadeDuration: 0,
      style: {
        version: 8,
        sources: { dem, relief: { ...dem } },
        layers: [
          { id: 'background', type: 'background', paint: { 'background-color': '#8fb4d8' } },
          { id: 'relief', type: 'color-relief', source: 'relief', paint: { 'color-relief-color': [
            'interpolate', ['linear'], ['elevation'], 0, '#5f8f45', 450, '#8fae5d', 1050, '#c9b57c',
            1900, '#9a6a45', 2850, '#7d5a4a', 3400, '#b8b0aa', 3800, '#f4f4f4'] } },
          { id: 'hillshade', type: 'hillshade', source: 'relief',
            paint: { 'hillshade-exaggeration': 0.6, 'hillshade-shadow-color': '#2b2118' } },
        ],
        terrain: { source: 'dem', exaggeration: 1 },
        sky: { 'sky-color': '#6f9fd8', 'horizon-color': '#d6e6f5', 'sky-horizon-blend': 0.6 },
      },
    });
    this.map = map;
    return new Promise((resolve, reject) => {
      const timer = setTimeout(() => reject(new Error(`map not idle after ${timeoutMs} ms`)), timeoutMs);
      map.on('error', (e) => console.error(`map error: ${e.error && e.error.message}`));
      map.once('idle', () => {
        clearTimeout(timer);
        try { resolve(this.state()); } catch (e) { reject(e); }
      });
    });
  },

  // The terrain's drawn tiles' zooms and the zooms of the DEM tiles they read (MapLibre draws
  // terrain tiles of 512 px: a DEM zoom one less, or the tree's deepest), the view's bounds and
  // tile zoom.
  state() {
    const map = this.map;
    const index = map.terrain && map.terrain.getCoverageIndex();
    const demZooms = new Set();
    if (map.terrain) {
      const tm = map.terrain.tileManager;
      for (const t of tm.getRenderableTiles()) {
        const source = tm.getSourceTile(t.tileID, true);
        if (source) demZooms.add(source.tileID.canonical.z);
      }
    }
    const b = map.getBounds();
    const transform = map.transform || (map._camera && map._camera.transform);
    return { zooms: index ? index.zooms : [], demZooms: [...demZooms].sort(), tileZoom: transform ? transform.tileZoom : null,
      bounds: [b.getWest(), b.getSouth(), b.getEast(), b.getNorth()],
      exaggeration: map.terrain ? map.terrain.exaggeration : null };
  },

  // map.queryTerrainElevation at [lon, lat], and whether that point's drawn tile has its own DEM
  // data (not a parent's).
  sample(points) {
    const map = this.map;
    return points.map(([lng, lat]) => {
      const own = map.terrain.getDrawnElevationForLngLat(new maplibregl.LngLat(lng, lat), true);
      return [map.queryTerrainElevation([lng, lat]), own !== undefined];
    });
  },

  // Moves the camera and resolves on the next idle event.
  jumpTo(options, timeoutMs = 90000) {
    const map = this.map;
    return new Promise((resolve, reject) => {
      const timer = setTimeout(() => reject(new Error(`map not idle after ${timeoutMs} ms`)), timeoutMs);
      map.once('idle', () => {
        clearTimeout(timer);
        try { resolve(this.state()); } catch (e) { reject(e); }
      });
      map.jumpTo(options);
    });
  },

  capture() {
    return this.map.getCanvas().toDataURL('image/png');
  },
};
window.globeTestReady = true;
