// Runs the Khronos glTF validator (npm package gltf-validator) over every .gltf/.glb file of a
// directory. Prints each file's error/warning/info counts and its errors and warnings; exits 1 if
// any file has an error or a warning, or if there is no file at all.
'use strict';
const fs = require('fs');
const path = require('path');

const [validatorDir, samplesDir] = process.argv.slice(2);
const validator = require(path.join(validatorDir, 'node_modules', 'gltf-validator'));

// A document with a known error (an accessor without its required count), so that a validator
// that silently accepts everything cannot make this test pass.
async function validatorIsLive() {
  const broken = {asset: {version: '2.0'}, accessors: [{componentType: 5126, type: 'VEC3'}]};
  const bytes = new TextEncoder().encode(JSON.stringify(broken));
  const report = await validator.validateBytes(bytes, {uri: 'broken.gltf'});
  return report.issues.numErrors > 0;
}

async function main() {
  if (!(await validatorIsLive())) {
    console.error('the validator reports no error on a broken document');
    return 1;
  }
  const files = fs.readdirSync(samplesDir).filter((f) => /\.(gltf|glb)$/.test(f)).sort();
  if (files.length === 0) {
    console.error(`no .gltf or .glb file in ${samplesDir}`);
    return 1;
  }
  let errors = 0;
  let warnings = 0;
  for (const file of files) {
    const bytes = new Uint8Array(fs.readFileSync(path.join(samplesDir, file)));
    const report = await validator.validateBytes(bytes, {
      uri: file,
      maxIssues: 0,  // no limit
      externalResourceFunction: (uri) => Promise.reject(new Error(`external resource ${uri}`)),
    });
    const issues = report.issues;
    console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
                `${issues.numInfos} infos, ${issues.numHints} hints (validator ${report.validatorVersion})`);
    for (const message of issues.messages) {
      if (message.severity <= 1) {  // 0 error, 1 warning
        const kind = message.severity === 0 ? 'ERROR' : 'warning';
        console.log(`  ${kind} ${message.code} at ${message.pointer || '-'}: ${message.message}`);
      }
    }
    const infoCodes = [...new Set(issues.messages.filter((m) => m.severity >= 2).map((m) => m.code))];
    if (infoCodes.length) console.log(`  infos/hints: ${infoCodes.join(', ')}`);
    if (process.env.HULLCOOK_VALIDATOR_VERBOSE) {
      for (const m of issues.messages) console.log(`  ${m.code} at ${m.pointer}: ${m.message}`);
    }
    errors += issues.numErrors;
    warnings += issues.numWarnings;
  }
  console.log(`${files.length} files: ${errors} errors, ${warnings} warnings`);
  return errors === 0 && warnings === 0 ? 0 : 1;
}

main().then((code) => process.exit(code), (error) => {
  console.error(error);
  process.exit(1);
});
