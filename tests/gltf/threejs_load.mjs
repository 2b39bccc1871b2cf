// Loads hullcook's .glb files with three.js's GLTFLoader under node, as a web game would, and
// checks that every asset node's mesh holds the finest level's hull vertices that
// `hullcook inspect --json` prints: exactly for the plain file, within 1e-9 for --meshopt
// (GLTFLoader with three's MeshoptDecoder; the node transform dequantizes), and within Draco's
// quantization step for --draco (vertices are deduplicated and reordered, so as sets).
//
// Draco: three's DRACOLoader decodes in a Web Worker, which node does not have; DracoInProcess
// below is a DRACOLoader whose decodeGeometry runs the same decoding steps as DRACOLoader's worker
// in-process, with the draco3dgltf npm decoder. Everything else (GLTFLoader's
// KHR_draco_mesh_compression extension, DRACOLoader's geometry building) is three's own code.
//
// Usage: node threejs_load.mjs HULLCOOK SPRITES_DIR WORK_DIR NODE_MODULES_PARENT
import fs from 'node:fs';
import path from 'node:path';
import {execFileSync} from 'node:child_process';
import {createRequire} from 'node:module';
import {pathToFileURL} from 'node:url';

const [hullcook, sprites, work, modulesParent] = process.argv.slice(2);
const modules = path.join(modulesParent, 'node_modules');
const load = (file) => import(pathToFileURL(path.join(modules, file)).href);
const THREE = await load('three/build/three.module.js');
const {GLTFLoader} = await load('three/examples/jsm/loaders/GLTFLoader.js');
const {DRACOLoader} = await load('three/examples/jsm/loaders/DRACOLoader.js');
const {MeshoptDecoder} = await load('three/examples/jsm/libs/meshopt_decoder.module.js');
const draco3dgltf = createRequire(import.meta.url)(path.join(modules, 'draco3dgltf'));
const draco = await draco3dgltf.createDecoderModule({});

class DracoInProcess extends DRACOLoader {
  preload() { return this; }
  // DRACOLoader's worker: decodeGeometry, decodeIndex and decodeAttribute, with unique ids as
  // glTF uses them.
  async decodeGeometry(buffer, taskConfig) {
    const decoder = new draco.Decoder();
    const array = new Int8Array(buffer);
    if (decoder.GetEncodedGeometryType(array) !== draco.TRIANGULAR_MESH) {
      throw new Error('not a Draco triangle mesh');
    }
    const mesh = new draco.Mesh();
    const status = decoder.DecodeArrayToMesh(array, array.byteLength, mesh);
    if (!status.ok() || mesh.ptr === 0) throw new Error('Draco decoding failed: ' + status.error_msg());
    const geometry = {index: null, attributes: []};
    for (const name in taskConfig.attributeIDs) {
      const type = globalThis[taskConfig.attributeTypes[name]];
      if (type !== Float32Array) throw new Error(`attribute ${name}: ${taskConfig.attributeTypes[name]}`);
      const attribute = decoder.GetAttributeByUniqueId(mesh, taskConfig.attributeIDs[name]);
      const values = mesh.num_points() * attribute.num_components();
      const ptr = draco._malloc(values * 4);
      decoder.GetAttributeDataArrayForAllPoints(mesh, attribute, draco.DT_FLOAT32, values * 4, ptr);
      geometry.attributes.push({name, array: new Float32Array(draco.HEAPF32.buffer, ptr, values).slice(),
                                itemSize: attribute.num_components()});
      draco._free(ptr);
    }
    const indices = mesh.num_faces() * 3;
    const ptr = draco._malloc(indices * 4);
    decoder.GetTrianglesUInt32Array(mesh, indices * 4, ptr);
    geometry.index = {array: new Uint32Array(draco.HEAPF32.buffer, ptr, indices).slice(), itemSize: 1};
    draco._free(ptr);
    draco.destroy(mesh);
    draco.destroy(decoder);
    return this._createGeometry(geometry);
  }
}

let failures = 0;
function fail(message) {
  if (failures < 20) console.log('  FAIL ' + message);
  ++failures;
}

async function check(variant, flags) {
  const file = path.join(work, `sprites_${variant}.glb`);
  execFileSync(hullcook, ['cook', sprites, '--tau', '2', '--ppu', '32', '-q', '-o', file, ...flags]);
  const expected = JSON.parse(execFileSync(hullcook, ['inspect', '--json', file],
                                           {maxBuffer: 1 << 28}).toString()).assets;
  const loader = new GLTFLoader();
  loader.setMeshoptDecoder(MeshoptDecoder);
  loader.setDRACOLoader(new DracoInProcess());
  const bytes = fs.readFileSync(file);
  const gltf = await loader.parseAsync(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.length), '');
  const nodes = gltf.scene.children;
  if (nodes.length !== expected.length) fail(`${variant}: ${nodes.length} nodes for ${expected.length} assets`);
  let vertices = 0;
  for (let a = 0; a < Math.min(nodes.length, expected.length); ++a) {
    const node = nodes[a], asset = expected[a];
    if (node.name !== THREE.PropertyBinding.sanitizeNodeName(asset.name)) fail(`${variant}: node ${a} is ${node.name}`);
    if (node.userData?.hullcook?.version !== 2) fail(`${variant} ${asset.name}: no extras version 2`);
    const hulls = asset.levels.length ? asset.levels[0].hulls : [];
    const points = hulls.flat();
    if (!node.isMesh) {
      if (points.length) fail(`${variant} ${asset.name}: no mesh`);
      continue;
    }
    node.updateMatrixWorld(true);
    const position = node.geometry.attributes.position;
    const read = [];
    for (let i = 0; i < position.count; ++i) {
      const v = new THREE.Vector3().fromBufferAttribute(position, i).applyMatrix4(node.matrixWorld);
      read.push([v.x, v.y, v.z]);
    }
    const triangles = hulls.reduce((sum, hull) => sum + Math.max(0, hull.length - 2), 0);
    if (node.geometry.index.count !== 3 * triangles) {
      fail(`${variant} ${asset.name}: ${node.geometry.index.count / 3} triangles, expected ${triangles}`);
    }
    if (variant !== 'draco') {
      if (read.length !== points.length) fail(`${variant} ${asset.name}: ${read.length} vertices, expected ${points.length}`);
      for (let i = 0; i < Math.min(read.length, points.length); ++i) {
        const [x, y] = points[i];
        const ok = variant === 'plain'
            ? read[i][0] === Math.fround(x) && read[i][1] === Math.fround(y)
            : Math.abs(read[i][0] - x) <= 1e-9 * Math.max(1, Math.abs(x)) &&
              Math.abs(read[i][1] - y) <= 1e-9 * Math.max(1, Math.abs(y));
        if (!ok || read[i][2] !== 0) fail(`${variant} ${asset.name} vertex ${i}: ${read[i]} for ${points[i]}`);
      }
    } else {
      // Draco: each expected vertex has a decoded one within the quantization step, and back.
      const xs = points.map((p) => p[0]), ys = points.map((p) => p[1]);
      const extent = Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys));
      const bound = extent / 65535 * (1 + 1e-6) + 1e-7 * Math.max(1, extent);
      const near = (p, q) => Math.abs(p[0] - q[0]) <= bound && Math.abs(p[1] - q[1]) <= bound;
      for (const p of points) if (!read.some((q) => near(p, q))) fail(`draco ${asset.name}: ${p} not decoded`);
      for (const q of read) if (!points.some((p) => near(p, q))) fail(`draco ${asset.name}: ${q} decoded, not expected`);
    }
    vertices += points.length;
  }
  console.log(`${variant}: ${path.basename(file)}, ${bytes.length} bytes, ${nodes.length} asset nodes, ` +
              `${vertices} finest-level vertices checked`);
  if (vertices === 0) fail(`${variant}: no vertex checked`);
}

await check('plain', []);
await check('meshopt', ['--meshopt']);
await check('draco', ['--draco']);
console.log(failures ? `${failures} failures` : 'three.js loads every variant with the hulls inspect prints');
process.exit(failures ? 1 : 0);
