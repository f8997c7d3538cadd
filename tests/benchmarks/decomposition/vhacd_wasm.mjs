// Runs V-HACD 4 (the WASM build in npm's vhacd-js) on every WORK/<name>/input.obj and writes
// WORK/<name>/vhacd_wasm.obj (one `o` group per hull) and vhacd_wasm.time (seconds spent in
// computeConvexHulls, module start-up excluded).
// usage: node vhacd_wasm.mjs VHACD_JS_DIR WORK MAX_HULLS
import fs from "node:fs";
import path from "node:path";
import { pathToFileURL } from "node:url";

const [vhacdDir, work, maxHulls] = process.argv.slice(2);
const { ConvexMeshDecomposition } = await import(pathToFileURL(path.join(vhacdDir, "lib", "vhacd.js")).href);
const decomposer = await ConvexMeshDecomposition.create();

function readObj(file) {
  const positions = [], indices = [];
  for (const line of fs.readFileSync(file, "utf8").split("\n")) {
    const p = line.trim().split(/\s+/);
    if (p[0] === "v") positions.push(+p[1], +p[2], +p[3]);
    else if (p[0] === "f") indices.push(...p.slice(1, 4).map((x) => parseInt(x, 10) - 1));
  }
  return { positions: new Float64Array(positions), indices: new Uint32Array(indices) };
}

for (const name of fs.readdirSync(work).sort()) {
  const input = path.join(work, name, "input.obj");
  if (!fs.existsSync(input)) continue;
  const mesh = readObj(input);
  const start = performance.now();
  const hulls = decomposer.computeConvexHulls(mesh, { maxHulls: Number(maxHulls) });
  const seconds = (performance.now() - start) / 1000;
  let out = "", base = 1;
  hulls.forEach((h, i) => {
    out += `o hull_${i}\n`;
    for (let v = 0; v < h.positions.length; v += 3) out += `v ${h.positions[v]} ${h.positions[v + 1]} ${h.positions[v + 2]}\n`;
    for (let t = 0; t < h.indices.length; t += 3) out += `f ${h.indices[t] + base} ${h.indices[t + 1] + base} ${h.indices[t + 2] + base}\n`;
    base += h.positions.length / 3;
  });
  fs.writeFileSync(path.join(work, name, "vhacd_wasm.obj"), out);
  fs.writeFileSync(path.join(work, name, "vhacd_wasm.time"), `${seconds}\n`);
  console.log(`${name}: V-HACD wasm ${hulls.length} hulls, ${seconds.toFixed(2)} s`);
}
