// Side-by-side timing: Rabbit Ear's layer solver (npm `rabbit-ear`, installed to a scratch
// directory by run.sh, never into the project) on one FOLD file.
// Prints "STATES SECONDS" (seconds from reading the file to the count) or "error: ...".
const fs = require("fs");
const ear = require("rabbit-ear");
const file = process.argv[2];
try {
  const t0 = process.hrtime.bigint();
  const fold = JSON.parse(fs.readFileSync(file, "utf8"));
  const graph = ear.graph(fold);
  graph.populate();
  const folded = ear.graph(JSON.parse(JSON.stringify(graph)));
  folded.vertices_coords = ear.graph.makeVerticesCoordsFlatFolded(graph, 0);
  const solution = ear.layer.solver(folded);
  const secs = Number(process.hrtime.bigint() - t0) / 1e9;
  if (!solution) { console.log(`0 ${secs.toFixed(3)}`); process.exit(0); }
  const counts = solution.count();
  let total = 1n;
  for (const c of counts) total *= BigInt(c);
  console.log(`${total} ${secs.toFixed(3)}`);
} catch (e) {
  console.log(`error: ${String(e).split("\n")[0]}`);
}
