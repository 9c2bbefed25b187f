#!/usr/bin/env node
// SPDX-License-Identifier: MIT
// Validates .glb/.gltf files with the Khronos glTF-Validator and exits non-zero
// on any error or warning (infos and hints are printed, not fatal).
// Usage: node tools/validate_gltf.js <file>...   (after `npm ci` in tools/gltf-validator)
'use strict';

const fs = require('fs');
const path = require('path');

let validator;
try {
  validator = require(path.join(__dirname, 'gltf-validator', 'node_modules', 'gltf-validator'));
} catch (e) {
  console.error('gltf-validator is not installed: run `npm ci` in tools/gltf-validator');
  process.exit(2);
}

const kSeverity = ['error', 'warning', 'info', 'hint'];

async function validate(file) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  const folder = path.dirname(file);
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 0,  // report everything
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) => {
        fs.readFile(path.resolve(folder, decodeURIComponent(uri)), (err, data) =>
          err ? reject(err.toString()) : resolve(new Uint8Array(data)));
      }),
  });
  const issues = report.issues;
  for (const m of issues.messages) {
    console.log(`${file}: ${kSeverity[m.severity]} ${m.code} at ${m.pointer || '/'}: ${m.message}`);
  }
  console.log(`${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
              `${issues.numInfos} infos, ${issues.numHints} hints (glTF-Validator ${report.validatorVersion})`);
  return issues.numErrors === 0 && issues.numWarnings === 0;
}

async function main() {
  const files = process.argv.slice(2);
  if (files.length === 0) {
    console.error('usage: validate_gltf.js <file.glb|file.gltf>...');
    process.exit(2);
  }
  let ok = true;
  for (const file of files) {
    try {
      ok = (await validate(file)) && ok;
    } catch (e) {
      console.log(`${file}: cannot validate: ${e}`);
      ok = false;
    }
  }
  process.exit(ok ? 0 : 1);
}

main();
