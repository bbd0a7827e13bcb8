// The sky/terrain silhouette of a picture rendered against a black sky: for each column, the
// first row from the top whose pixel is not sky (r+g+b above a threshold); the height where the
// column is all sky. Decoded in the browser (a canvas), so no PNG library is needed here.
export async function silhouette(page, pngBuffer, threshold = 24) {
  const dataUrl = `data:image/png;base64,${Buffer.from(pngBuffer).toString('base64')}`;
  return page.evaluate(async (url, limit) => {
    const img = new Image();
    img.src = url;
    await img.decode();
    const c = document.createElement('canvas');
    c.width = img.width;
    c.height = img.height;
    const ctx = c.getContext('2d', { willReadFrequently: true });
    ctx.drawImage(img, 0, 0);
    const { data } = ctx.getImageData(0, 0, c.width, c.height);
    const rows = [];
    for (let x = 0; x < c.width; ++x) {
      let y = 0;
      for (; y < c.height; ++y) {
        const i = 4 * (y * c.width + x);
        if (data[i] + data[i + 1] + data[i + 2] > limit) break;
      }
      rows.push(y);
    }
    return { width: c.width, height: c.height, rows };
  }, dataUrl, threshold);
}

// Per-column |a - b| in pixels.
export function rowDifferences(a, b) {
  if (a.width !== b.width || a.height !== b.height) {
    throw new Error(`pictures of different sizes: ${a.width}x${a.height} and ${b.width}x${b.height}`);
  }
  return a.rows.map((r, i) => Math.abs(r - b.rows[i]));
}
