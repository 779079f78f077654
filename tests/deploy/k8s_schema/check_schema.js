// check_schema.js MANIFEST...: every document of each manifest validated
// against the Kubernetes API's JSON schema for its kind (kubernetes-models,
// pinned in package.json): field types, required fields, enumerations. The
// schemas allow unknown fields, so check_k8s.py checks the fields that matter
// by name. A deliberately wrong Deployment must be rejected, or the check
// proves nothing. Exit 1 on any invalid document.
"use strict";
const fs = require("fs");
const yaml = require("js-yaml");

const models = {
  "v1/ConfigMap": require("kubernetes-models/v1/ConfigMap").ConfigMap,
  "v1/Service": require("kubernetes-models/v1/Service").Service,
  "apps/v1/Deployment": require("kubernetes-models/apps/v1/Deployment").Deployment,
  "apps/v1/StatefulSet": require("kubernetes-models/apps/v1/StatefulSet").StatefulSet,
  "policy/v1/PodDisruptionBudget": require("kubernetes-models/policy/v1/PodDisruptionBudget").PodDisruptionBudget,
};

function validate(doc) {
  const Model = models[`${doc.apiVersion}/${doc.kind}`];
  if (!Model) throw new Error(`no schema here for ${doc.apiVersion} ${doc.kind}`);
  new Model(doc).validate();
}

let failures = 0;
for (const file of process.argv.slice(2)) {
  for (const doc of yaml.loadAll(fs.readFileSync(file, "utf8")).filter(Boolean)) {
    try {
      validate(doc);
      console.log(`valid: ${file}: ${doc.kind} ${doc.metadata.name}`);
    } catch (e) {
      failures++;
      console.log(`FAIL: ${file}: ${doc.kind} ${doc.metadata && doc.metadata.name}: ${e.message}`);
    }
  }
}

const wrong = {apiVersion: "apps/v1", kind: "Deployment", metadata: {name: "wrong"},
               spec: {selector: {}, template: {spec: {containers: [{name: "c", ports: [{containerPort: "http"}]}]}}}};
try {
  validate(wrong);
  failures++;
  console.log("FAIL: a containerPort given as a string passed the schema");
} catch (e) {
  console.log(`a deliberately wrong Deployment is rejected: ${e.message.split("\n")[0]}`);
}
process.exit(failures ? 1 : 0);
