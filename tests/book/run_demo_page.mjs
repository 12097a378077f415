// How tests/book/book_figures_test.cpp's pixel counts were obtained: runs one of the book's demo
// pages (demos/raster-06.html, -07, -08 of github.com/ggambetta/computer-graphics-from-scratch;
// not part of twinraster) under node with a stand-in 600 x 600 canvas, prints the number of
// pixels of each colour, and writes the canvas as a PNG for `twinraster compare`. The page's
// transparent pixels are written white, as the page shows them.
//
// usage: node tests/book/run_demo_page.mjs raster-08.html demo-08.png
import fs from "node:fs";
import vm from "node:vm";
import zlib from "node:zlib";

const [page, out] = process.argv.slice(2);
if (!page || !out) {
  console.error("usage: node run_demo_page.mjs PAGE.html OUT.png");
  process.exit(2);
}
const html = fs.readFileSync(page, "utf8");
const script = html.slice(html.indexOf("<script>") + "<script>".length, html.lastIndexOf("</script>"));

const width = 600, height = 600;
let shown = null;  // the ImageData the page last put on its canvas
const canvas = {
  width, height,
  getContext: () => ({
    getImageData: (x, y, w, h) => ({ width: w, height: h, data: new Uint8ClampedArray(w * h * 4) }),
    putImageData: (image) => { shown = image; },
  }),
};
vm.runInNewContext(script, { document: { getElementById: () => canvas }, console });
if (!shown) throw new Error(`${page} never put its canvas on the page`);

const rgba = Buffer.alloc(width * height * 4);
const counts = {};
for (let p = 0; p < width * height; ++p) {
  const [r, g, b, a] = shown.data.subarray(4 * p, 4 * p + 4);
  const colour = a === 0 ? [255, 255, 255] : [r, g, b];
  rgba.set([...colour, 255], 4 * p);
  const key = colour.join(",");
  if (key !== "255,255,255") counts[key] = (counts[key] || 0) + 1;
}
console.log(JSON.stringify(counts));

// A PNG with one unfiltered RGBA row after another.
const chunk = (type, data) => {
  const length = Buffer.alloc(4);
  length.writeUInt32BE(data.length);
  const body = Buffer.concat([Buffer.from(type, "ascii"), data]);
  const crc = Buffer.alloc(4);
  crc.writeUInt32BE(zlib.crc32(body));
  return Buffer.concat([length, body, crc]);
};
const header = Buffer.alloc(13);
header.writeUInt32BE(width, 0);
header.writeUInt32BE(height, 4);
header[8] = 8;  // bits per channel
header[9] = 6;  // RGBA
const rows = Buffer.alloc(height * (1 + width * 4));  // each row: filter byte 0, then its pixels
for (let y = 0; y < height; ++y) rgba.copy(rows, y * (1 + width * 4) + 1, y * width * 4, (y + 1) * width * 4);
fs.writeFileSync(out, Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk("IHDR", header),
                                     chunk("IDAT", zlib.deflateSync(rows)), chunk("IEND", Buffer.alloc(0))]));
