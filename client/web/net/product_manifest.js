// A product's manifest (product.json, protocol/PRODUCT.md), read as hostile input: anything
// that is not a version-1 Inkwire product whose every field is in range throws an Error with a
// one-line reason the element shows. Returns {name, product (as a snapshot's product block),
// photos, mattes, zoom (per level), cells}, each file {file, sha256, size} (cells with pair too).
export const kManifestVersion = 1;
const kMaxSamples = 360, kMaxLevels = 3, kMaxSide = 4096, kMaxFileBytes = 64 * 1024 * 1024, kMaxCells = 4096;

function fail(reason) { throw new Error(`the product's manifest: ${reason}`); }

function integer(value, lo, hi, what) {
  if (!Number.isInteger(value) || value < lo || value > hi) fail(`${what} is not a whole number in ${lo}..${hi}`);
  return value;
}

function number(value, lo, hi, what) {
  if (typeof value !== 'number' || !Number.isFinite(value) || value < lo || value > hi) fail(`${what} is not a number in ${lo}..${hi}`);
  return value;
}

// A file of the product: a relative path under files/ named by its hash, which it must match.
function file(entry, what) {
  if (typeof entry !== 'object' || entry === null) fail(`${what} is not a file`);
  const { file: path, sha256, size } = entry;
  if (typeof sha256 !== 'string' || !/^[0-9a-f]{64}$/.test(sha256)) fail(`${what} has no SHA-256`);
  if (typeof path !== 'string' || !/^files\/[0-9a-f]{64}\.(jpg|png|cell)$/.test(path) || !path.includes(sha256)) fail(`${what} is not files/ named by its hash`);
  return { file: path, sha256, size: integer(size, 1, kMaxFileBytes, `${what}'s size`) };
}

function list(value, what, max) {
  if (!Array.isArray(value) || value.length > max) fail(`${what} is not a list of at most ${max}`);
  return value;
}

export function parseManifest(text) {
  let m;
  try {
    m = JSON.parse(text);
  } catch {
    fail('not JSON');
  }
  if (typeof m !== 'object' || m === null || m.format !== 'inkwire-product') fail('not an Inkwire product');
  if (m.version !== kManifestVersion) fail(`version ${JSON.stringify(m.version)}, this element reads version ${kManifestVersion}`);
  if (typeof m.name !== 'string' || m.name.length > 64) fail('no name');
  const width = integer(m.width, 1, kMaxSide, 'width'), height = integer(m.height, 1, kMaxSide, 'height');
  const directions = list(m.directions, 'directions', kMaxSamples).map((d, i) => {
    if (!Array.isArray(d) || d.length !== 3) fail(`direction ${i} is not three numbers`);
    const v = d.map((x) => number(x, -1, 1, `direction ${i}`));
    if (Math.abs(Math.hypot(...v) - 1) > 0.01) fail(`direction ${i} is not a unit vector`);
    return v;
  });
  if (directions.length < 2) fail('fewer than two photos');
  const levels = list(m.levels, 'levels', kMaxLevels).map((l, i) => ({
    width: integer(l?.width, 1, kMaxSide, `level ${i + 1}'s width`), height: integer(l?.height, 1, kMaxSide, `level ${i + 1}'s height`),
  }));
  const photos = list(m.photos, 'photos', kMaxSamples).map((f, i) => file(f, `photo ${i}`));
  const mattes = list(m.mattes, 'mattes', kMaxSamples).map((f, i) => file(f, `matte ${i}`));
  if (photos.length !== directions.length) fail(`${photos.length} photos for ${directions.length} directions`);
  if (mattes.length !== 0 && mattes.length !== photos.length) fail(`${mattes.length} mattes for ${photos.length} photos`);
  const zoom = list(m.zoom, 'zoom', kMaxLevels).map((level, l) => list(level, `zoom level ${l + 1}`, kMaxSamples).map((f, i) => file(f, `zoom ${l + 1} photo ${i}`)));
  if (zoom.length !== levels.length || zoom.some((level) => level.length !== photos.length)) fail('the zoom photos do not match the levels');
  const cells = list(m.cells, 'cells', kMaxCells).map((c, i) => ({ ...file(c, `cell ${i}`), pair: integer(c?.pair, 0, kMaxCells - 1, `cell ${i}'s pair`) }));
  if (cells.some((c, i) => c.pair !== i)) fail('the cells are not in pair order');
  const product = { width, height, directions, cells: cells.length, levels,
                    distance_diagonals: number(m.distance_diagonals, 0.01, 100, 'distance'), fov_y_degrees: number(m.fov_y_degrees, 1, 179, 'field of view') };
  return { name: m.name, product, photos, mattes, zoom, cells };
}
