// The glTF's provenance: per primitive, records of four uint32 (first element,
// element count, module index, module id) sorted by first element, in the
// buffer view its extras name (studio_api.md).
const RECORD = 4;

export async function recordsOf(model, primitive) {
  const geometry = primitive.geometry;
  if (geometry.userData.sylvaRecords) return geometry.userData.sylvaRecords;
  const provenance = geometry.userData.sylva_provenance;
  if (!provenance) return null;
  const bytes = await model.parser.getDependency('bufferView', provenance.bufferView);
  const records = new Uint32Array(bytes, 0, Math.min(provenance.count * RECORD, Math.floor(bytes.byteLength / 4)));
  geometry.userData.sylvaRecords = records;
  return records;
}

// The record whose elements hold `element`, or null.
export function recordOfElement(records, element) {
  let low = 0;
  let high = records.length / RECORD - 1;
  let found = -1;
  while (low <= high) {
    const middle = (low + high) >> 1;
    if (records[middle * RECORD] <= element) {
      found = middle;
      low = middle + 1;
    } else {
      high = middle - 1;
    }
  }
  if (found < 0) return null;
  const at = found * RECORD;
  const [first, count, module, id] = records.subarray(at, at + RECORD);
  return element < first + count ? { first, count, module, id } : null;
}

// The element a ray hit: a triangle of a mesh, a segment of lines, a point.
export function elementOfHit(hit) {
  const object = hit.object;
  if (object.isMesh) return hit.faceIndex;
  if (object.isLineSegments) return Math.floor(hit.index / 2);
  return hit.index;
}

export function elementSize(primitive) {
  if (primitive.isMesh) return 3;
  if (primitive.isLineSegments) return 2;
  return 1;
}

// Every range of elements, over all primitives, that module `index` made; an
// instance of an instanced primitive is a range of its own ({primitive, instance}).
export async function rangesOfModule(model, index) {
  const ranges = [];
  for (const primitive of model.primitives) {
    if (primitive.isInstancedMesh) {
      const indices = primitive.userData.moduleIndices;
      for (let i = 0; i < indices.length; ++i)
        if (indices[i] === index) ranges.push({ primitive, instance: i, first: i, count: 1 });
      continue;
    }
    const records = await recordsOf(model, primitive);
    if (!records) continue;
    for (let at = 0; at < records.length; at += RECORD) {
      if (records[at + 2] === index) ranges.push({ primitive, first: records[at], count: records[at + 1] });
    }
  }
  return ranges;
}
