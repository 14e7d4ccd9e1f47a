// The Khronos glTF validator's verdict on each file named on the command line, one line per file:
// file<TAB>number of errors<TAB>their codes (unique, comma-separated) or "-".
// External resources are read from the file's folder (no further than 64 MiB each); FIFOs and other
// special files are never opened. Used by tests/validator/crosscheck.sh only.
import { readFile, stat } from "node:fs/promises";
import path from "node:path";
import validator from "gltf-validator";

async function readResource(folder, uri) {
  const file = path.resolve(folder, decodeURIComponent(uri));
  const s = await stat(file);
  if (!s.isFile() || s.size > 64 * 1024 * 1024) throw new Error(`${uri}: not a regular file of at most 64 MiB`);
  return new Uint8Array(await readFile(file));
}

for (const file of process.argv.slice(2)) {
  let errors = "?", codes = "-";
  try {
    const s = await stat(file);
    if (!s.isFile()) throw new Error("not a regular file");
    const report = await validator.validateBytes(new Uint8Array(await readFile(file)), {
      uri: path.basename(file),
      maxIssues: 0,
      externalResourceFunction: (uri) => readResource(path.dirname(file), uri),
    });
    errors = report.issues.numErrors;
    const seen = [...new Set(report.issues.messages.filter((m) => m.severity === 0).map((m) => m.code))];
    if (seen.length) codes = seen.join(",");
  } catch (e) {
    errors = 1;  // the validator could not read it at all: that is its verdict too
    codes = "VALIDATOR_FAILED:" + String(e && e.message ? e.message : e).replace(/\s+/g, " ").slice(0, 80);
  }
  process.stdout.write(`${file}\t${errors}\t${codes}\n`);
}
