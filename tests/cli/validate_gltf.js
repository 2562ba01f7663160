// validate_gltf.js — the Khronos glTF validator (npm's gltf-validator) over .glb files.
// Prints one line of counts per file, then each issue; exits 1 if any file has an error.
// Usage: NODE_PATH=DIR/node_modules node validate_gltf.js FILE.glb...
const fs = require('fs');
const validator = require('gltf-validator');

(async () => {
    let errors = 0;
    for (const file of process.argv.slice(2)) {
        const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)),
                                                     {maxIssues: 100});
        const i = report.issues;
        console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ` +
                    `${i.numInfos} infos, ${i.numHints} hints`);
        for (const m of i.messages) console.log(`  ${m.severity} ${m.code} ${m.pointer}: ${m.message}`);
        errors += i.numErrors;
    }
    process.exit(errors ? 1 : 0);
})().catch((e) => {
    console.log(`validator failed: ${e}`);
    process.exit(1);
});
