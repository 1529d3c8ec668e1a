#!/usr/bin/env node
// Runs the Khronos glTF validator (npm package gltf-validator, pinned in
// package-lock.json) over each FILE and prints one summary line per file.
// Exit status: 0 if every file has no errors and no warnings (infos and hints
// are allowed but counted), 1 if any file has errors or warnings, 2 on usage
// or I/O problems. Errors and warnings are listed under their file so a CI
// log says what broke without re-running.
'use strict';

const fs = require('fs');
const path = require('path');
const validator = require('gltf-validator');

const SEVERITY = ['error', 'warning', 'info', 'hint'];

function loadExternal(file) {
  // Only used for .gltf files that reference external buffers or images.
  return (uri) => new Promise((resolve, reject) => {
    const full = path.resolve(path.dirname(file), decodeURIComponent(uri));
    fs.readFile(full, (err, data) => (err ? reject(err.toString()) : resolve(data)));
  });
}

async function validateFile(file) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 1000000,
    writeTimestamp: false,
    externalResourceFunction: loadExternal(file),
  });
  const issues = report.issues;
  const bad = issues.numErrors > 0 || issues.numWarnings > 0;
  console.log(`${file}: ${bad ? 'FAIL' : 'OK'} errors=${issues.numErrors} ` +
              `warnings=${issues.numWarnings} infos=${issues.numInfos} hints=${issues.numHints}`);
  for (const m of issues.messages) {
    if (m.severity <= 1 || process.env.GLTF_VALIDATE_VERBOSE) {
      console.log(`  ${SEVERITY[m.severity]} ${m.code} at ${m.pointer || '/'}: ${m.message}`);
    }
  }
  return bad;
}

async function main(files) {
  if (files.length === 0) {
    console.error('usage: node validate.js FILE.glb|FILE.gltf...');
    return 2;
  }
  let status = 0;
  for (const file of files) {
    try {
      if (await validateFile(file)) status = Math.max(status, 1);
    } catch (err) {
      console.log(`${file}: FAIL cannot validate: ${err}`);
      status = 2;
    }
  }
  return status;
}

main(process.argv.slice(2)).then((code) => { process.exitCode = code; });
