// Compiles MJCF models with MuJoCo itself (npm @mujoco/mujoco: the official WebAssembly build,
// MuJoCo 3.14) and prints, as JSON, what its compiler made of them: per joint its range,
// damping, armature and joint-space inertia at qpos0; per actuator its gains, gear and ranges,
// and the inertia it reflects at qpos0 both ways MuJoCo has defined it (below); the joint
// equalities.
//
//   node compile.mjs <@mujoco/mujoco package dir> <model.xml>...
//
// Each model and the files it <include>s are written into MuJoCo's in-memory file system at
// their paths relative to the model. Mesh and texture files that are absent (public models are
// often checked without their assets) are replaced by stand-ins: a cube for a mesh, one pixel
// for a texture. A stand-in mesh changes nothing this script reports as long as the body that
// holds it states its own <inertial> (MuJoCo then ignores geom inertia). Where a body's mass
// comes from its geoms and one of them is a stand-in, every quantity that depends on it (the
// joint-space inertia of the joints moving it, a kv derived from dampratio) is reported as
// excluded, with the body named, instead of a number.
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { pathToFileURL } from 'node:url';

const [packageDir, ...models] = process.argv.slice(2);
if (!packageDir || models.length === 0) {
  console.error('usage: node compile.mjs <@mujoco/mujoco package dir> <model.xml>...');
  process.exit(2);
}
const load = (await import(pathToFileURL(path.join(packageDir, 'mujoco.js')).href)).default;
// MuJoCo prints its runtime warnings (a full contact buffer at the first step, …) on the
// module's stdout, where this script writes its JSON: send them to stderr.
const mj = await load({ print: (text) => process.stderr.write(`${text}\n`), printErr: (text) => process.stderr.write(`${text}\n`) });

// The <include file=...> names in a text (MuJoCo resolves them against the model's directory).
function includes(text) {
  return [...text.matchAll(/<include\b[^>]*\bfile\s*=\s*"([^"]*)"/g)].map((m) => m[1]);
}

// The model with every <include> replaced by the children of the included file's root, for
// MuJoCo's string parser, which cannot open files; and the files it read, relative to `dir`.
function inline(file, dir, read = new Set()) {
  const text = fs.readFileSync(file, 'utf8');
  read.add(path.relative(dir, file));
  const flat = text.replace(/<include\b[^>]*\bfile\s*=\s*"([^"]*)"[^>]*\/>/g, (_, name) => {
    const inner = inline(path.resolve(dir, name), dir, read).text;
    const body = inner.replace(/<\?xml[^>]*>/, '').replace(/<!--[\s\S]*?-->/g, '');
    const open = body.match(/<mujoco\b[^>]*>/);
    if (!open) return '';
    return body.slice(open.index + open[0].length, body.lastIndexOf('</mujoco>'));
  });
  return { text: flat, read };
}

// A closed cube of side 1 (large enough to keep a volume after a mesh scale of 0.001): binary STL, OBJ.
const cube = (() => {
  const v = [];
  for (const x of [-1, 1]) for (const y of [-1, 1]) for (const z of [-1, 1]) v.push([x * 0.5, y * 0.5, z * 0.5]);
  const faces = [[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                 [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]];
  const stl = Buffer.alloc(84 + 50 * faces.length);
  stl.writeUInt32LE(faces.length, 80);
  faces.forEach((f, i) => {
    f.forEach((vi, k) => v[vi].forEach((c, a) => stl.writeFloatLE(c, 84 + 50 * i + 12 + 12 * k + 4 * a)));
  });
  const obj = v.map((p) => `v ${p.join(' ')}`).concat(faces.map((f) => `f ${f.map((i) => i + 1).join(' ')}`)).join('\n');
  return { stl, obj: Buffer.from(obj + '\n') };
})();
// An 8×8 white PNG.
const pixel = (() => {
  const crcTable = Array.from({ length: 256 }, (_, n) => {
    let c = n;
    for (let k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    return c >>> 0;
  });
  const crc = (bytes) => {
    let c = 0xffffffff;
    for (const b of bytes) c = crcTable[(c ^ b) & 0xff] ^ (c >>> 8);
    return (c ^ 0xffffffff) >>> 0;
  };
  const chunk = (type, data) => {
    const body = Buffer.concat([Buffer.from(type, 'ascii'), data]);
    const out = Buffer.alloc(body.length + 8);
    out.writeUInt32BE(data.length, 0);
    body.copy(out, 4);
    out.writeUInt32BE(crc(body), body.length + 4);
    return out;
  };
  const header = Buffer.alloc(13);
  header.writeUInt32BE(8, 0);
  header.writeUInt32BE(8, 4);
  header[8] = 8;  // bit depth
  header[9] = 2;  // RGB
  const rows = Buffer.alloc(8 * (1 + 8 * 3), 0xff);
  for (let r = 0; r < 8; ++r) rows[r * 25] = 0;  // filter: none
  return Buffer.concat([Buffer.from('89504e470d0a1a0a', 'hex'), chunk('IHDR', header),
                        chunk('IDAT', zlib.deflateSync(rows)), chunk('IEND', Buffer.alloc(0))]);
})();

function mkdirs(dir) {
  let at = '';
  for (const part of dir.split('/').filter(Boolean)) {
    at += '/' + part;
    try { mj.FS.mkdir(at); } catch { /* exists */ }
  }
}
function put(file, bytes) {
  mkdirs(path.posix.dirname(file));
  mj.FS.writeFile(file, bytes);
}

function* elements(spec, type) {
  for (let e = mj.mjs_firstElement(spec, type); e; e = mj.mjs_nextElement(spec, e)) yield e;
}

// MuJoCo's compiler errors arrive as JavaScript errors whose message is MuJoCo's text.
function describe(err) {
  return String(err?.message ?? err).replace(/\s+/g, ' ').trim();
}

// The inverse of a small symmetric positive definite n×n matrix (row-major), by Cholesky; null
// when it is not positive definite.
function invert(a, n) {
  const L = new Float64Array(n * n);
  for (let j = 0; j < n; ++j) {
    let diag = a[j * n + j];
    for (let k = 0; k < j; ++k) diag -= L[j * n + k] * L[j * n + k];
    if (!(diag > 0)) return null;
    L[j * n + j] = Math.sqrt(diag);
    for (let i = j + 1; i < n; ++i) {
      let v = a[i * n + j];
      for (let k = 0; k < j; ++k) v -= L[i * n + k] * L[j * n + k];
      L[i * n + j] = v / L[j * n + j];
    }
  }
  const inv = new Array(n * n).fill(0);
  for (let c = 0; c < n; ++c) {
    const y = new Float64Array(n);  // L y = e_c, then Lᵀ x = y
    for (let i = 0; i < n; ++i) {
      let v = i === c ? 1 : 0;
      for (let k = 0; k < i; ++k) v -= L[i * n + k] * y[k];
      y[i] = v / L[i * n + i];
    }
    for (let i = n - 1; i >= 0; --i) {
      let v = y[i];
      for (let k = i + 1; k < n; ++k) v -= L[k * n + i] * inv[k * n + c];
      inv[i * n + c] = v / L[i * n + i];
    }
  }
  return inv;
}

// The model's boolean arrays (jnt_limited, actuator_ctrllimited, …): the bindings of 3.14 cannot
// hand out mjtByte arrays, so they are read from mj_printModel's listing, which gives each
// element a section ("JOINT 3:") with one line per field.
function booleans(m) {
  mj.mj_printModel(m, '/listing.txt');
  const values = new Map();
  let section = null;
  for (const line of mj.FS.readFile('/listing.txt', { encoding: 'utf8' }).split('\n')) {
    const head = line.match(/^([A-Z_]+) (\d+):\s*$/);
    if (head) { section = `${head[1]} ${head[2]}`; continue; }
    const field = line.match(/^\s+(\w+limited|eq_active0)\s+(-?\d+)/);
    if (section && field) values.set(`${section} ${field[1]}`, field[2] === '1');
  }
  mj.FS.unlink('/listing.txt');
  return (kind, index, key) => {
    const v = values.get(`${kind} ${index} ${key}`);
    if (v === undefined) throw new Error(`mj_printModel lists no ${key} for ${kind} ${index}`);
    return v;
  };
}

let run = 0;
function compile(modelPath) {
  const dir = path.dirname(path.resolve(modelPath));
  const { text, read } = inline(path.resolve(modelPath), dir);
  const root = `/run${run++}`;
  for (const rel of read) put(path.posix.join(root, rel), fs.readFileSync(path.resolve(dir, rel)));

  const spec = mj.parseXMLString(text);
  const compiler = spec.compiler;
  const assetDir = (kind) => (kind === 'mesh' ? compiler.meshdir : compiler.texturedir) || '';
  const standins = [];
  const standinMeshes = new Set();
  const supply = (kind, name, file) => {
    if (!file) return;
    const rel = path.join(assetDir(kind), spec.strippath ? path.basename(file) : file);
    const onDisk = path.resolve(dir, rel);
    const inFs = path.posix.join(root, rel);
    if (fs.existsSync(onDisk)) { put(inFs, fs.readFileSync(onDisk)); return; }
    const ext = path.extname(file).toLowerCase();
    put(inFs, kind === 'texture' ? pixel : ext === '.obj' ? cube.obj : cube.stl);
    standins.push(rel);
    if (kind === 'mesh') standinMeshes.add(name);
  };
  for (const e of elements(spec, mj.mjtObj.mjOBJ_MESH)) supply('mesh', mj.mjs_getName(e), mj.mjs_asMesh(e).file);
  for (const e of elements(spec, mj.mjtObj.mjOBJ_TEXTURE)) supply('texture', mj.mjs_getName(e), mj.mjs_asTexture(e).file);
  // A cube texture's six faces and a height field's image: images too.
  for (const [, attrs] of text.matchAll(/<texture\b([^>]*)>/g))
    for (const [, face] of attrs.matchAll(/\bfile(?:right|left|up|down|front|back)\s*=\s*"([^"]*)"/g)) supply('texture', null, face);
  for (const [, attrs] of text.matchAll(/<hfield\b([^>]*)>/g)) {
    const file = attrs.match(/\bfile\s*=\s*"([^"]*)"/);
    if (file) supply('mesh', null, file[1]);
  }

  // Bodies (document order = the compiled model's body order) whose mass properties MuJoCo
  // takes from their geoms, and which of those hold a stand-in mesh.
  const fromGeoms = compiler.inertiafromgeom === mj.mjtInertiaFromGeom.mjINERTIAFROMGEOM_TRUE;
  // Bodies whose <inertial> gives a full tensor: MuJoCo diagonalises it numerically
  // (mju_eig3), which is exact only to about 1e-6 relative.
  const guessed = [], diagonalised = [];
  for (const e of elements(spec, mj.mjtObj.mjOBJ_BODY)) {
    const body = mj.mjs_asBody(e);
    let standin = false, geoms = 0;
    if (fromGeoms || !body.explicitinertial) {
      for (let g = mj.mjs_firstChild(body, mj.mjtObj.mjOBJ_GEOM, 0); g; g = mj.mjs_nextChild(body, g, 0)) {
        if (standinMeshes.has(mj.mjs_asGeom(g).meshname)) standin = true;
        ++geoms;
      }
    }
    // Several geoms: MuJoCo sums their tensors and diagonalises the sum the same way.
    diagonalised.push((body.explicitinertial && !fromGeoms && !Number.isNaN(body.fullinertia[0])) || geoms > 1);
    guessed.push(standin);
  }
  // The damping ratio each actuator asks for (document order = the compiled model's order):
  // a position-like actuator (gainprm[0] = −biasprm[1]) with biasprm[2] > 0.
  const dampratios = [];
  for (const e of elements(spec, mj.mjtObj.mjOBJ_ACTUATOR)) {
    const a = mj.mjs_asActuator(e);
    dampratios.push(a.gainprm[0] === -a.biasprm[1] && a.biasprm[2] > 0 ? a.biasprm[2] : null);
  }
  spec.delete();

  let m;
  try {
    m = mj.MjModel.from_xml_path(path.posix.join(root, path.basename(modelPath)));
  } catch (err) {
    return { model: modelPath, error: describe(err) };
  }
  if (!m) return { model: modelPath, error: 'MuJoCo returned no model' };
  const d = new mj.MjData(m);
  mj.mj_forward(m, d);
  // Names straight from the model's name buffer (an unnamed element has an empty one).
  const names = Uint8Array.from(m.names, (b) => b & 0xff);
  const nameAt = (adr) => {
    const end = names.indexOf(0, adr);
    return end > adr ? Buffer.from(names.subarray(adr, end)).toString('utf8') : null;
  };
  const name = (kind, id) => nameAt(m[`name_${kind}adr`][id]);
  const flag = booleans(m);
  const O = { mjOBJ_BODY: 'body', mjOBJ_JOINT: 'jnt', mjOBJ_ACTUATOR: 'actuator' };

  // A body's subtree holds a body whose inertia came from a stand-in mesh.
  const tainted = new Array(m.nbody).fill(false), rounded = new Array(m.nbody).fill(false);
  if (guessed.length === m.nbody) {
    for (let b = m.nbody - 1; b > 0; --b) {
      if (guessed[b]) tainted[b] = true;
      if (diagonalised[b]) rounded[b] = true;
      if (tainted[b]) tainted[m.body_parentid[b]] = true;
      if (rounded[b]) rounded[m.body_parentid[b]] = true;
    }
  }
  const guessedBodies = guessed.map((g, b) => (g ? name(O.mjOBJ_BODY, b) ?? `#${b}` : null)).filter((x) => x !== null);
  const jointNames = ['free', 'ball', 'slide', 'hinge'];
  const joints = [];
  for (let j = 0; j < m.njnt; ++j) {
    const type = m.jnt_type[j];
    const ndof = [6, 3, 1, 1][type];
    const body = m.jnt_bodyid[j];
    const dofs = [];
    for (let k = 0; k < ndof; ++k) {
      const i = m.jnt_dofadr[j] + k;
      dofs.push({
        damping: m.dof_damping[i],
        armature: m.dof_armature[i],
        M0: tainted[body] ? null : m.dof_M0[i],
      });
    }
    joints.push({
      index: j,
      name: name(O.mjOBJ_JOINT, j),
      type: jointNames[type],
      body: name(O.mjOBJ_BODY, body),
      limited: flag('JOINT', j, 'jnt_limited'),
      range: [m.jnt_range[2 * j], m.jnt_range[2 * j + 1]],
      stiffness: m.jnt_stiffness[j],
      actfrclimited: flag('JOINT', j, 'jnt_actfrclimited'),
      actfrcrange: [m.jnt_actfrcrange[2 * j], m.jnt_actfrcrange[2 * j + 1]],
      dofs,
      inertia_excluded: tainted[body] ? 'a body it moves takes its mass from a stand-in mesh' : null,
      inertia_diagonalised: rounded[body],
    });
  }
  // M⁻¹·v by MuJoCo's own factorisation of the joint-space mass matrix at qpos0 (mj_forward
  // has factored it); a kinematic tree that moves a stand-in body reflects no known inertia.
  const nv = m.nv;
  const solveM = (v) => {
    const x = new mj.DoubleBuffer(nv);
    mj.mj_solveM(m, d, x, v);
    const out = Array.from(x.GetView());
    x.delete();
    return out;
  };
  const treeTainted = new Set();
  for (let b = 1; b < m.nbody; ++b)
    if (guessed.length === m.nbody && guessed[b] && m.body_weldid[b] !== 0) treeTainted.add(m.body_rootid[b]);

  const trnNames = ['joint', 'jointinparent', 'slidercrank', 'tendon', 'site', 'body', 'so3'];
  const actuators = [];
  for (let a = 0; a < m.nactuator; ++a) {
    const trn = m.actuator_trntype[a];
    const target = m.actuator_trnid[2 * a];
    const jointTrn = trn === 0 || trn === 1;
    const prm = (arr, n) => Array.from(arr.slice(n * a, n * a + 3));
    const kvExcluded = jointTrn && tainted[m.jnt_bodyid[target]];
    // Controls and force outputs have their own arrays since MuJoCo 3.11 (an actuator may have
    // several of each); gear is per force output, the control range per control.
    const ctrl = m.actuator_ctrladr[a], out = m.actuator_outadr[a], outs = m.actuator_outnum[a];
    // The moment rows (one per force output) at qpos0, sparse over the dofs.
    const rows = [];
    for (let k = out; k < out + outs; ++k) {
      const row = [];
      for (let n = 0, adr = d.moment_rowadr[k]; n < d.moment_rownnz[k]; ++n)
        row.push([d.moment_colind[adr + n], d.actuator_moment[adr + n]]);
      rows.push(row);
    }
    // Up to 3.14: Σ dof_M0 / moment² over the first output's dofs. From 3.15: the
    // operational-space inertia (J M⁻¹ Jᵀ)⁻¹ at qpos0, its diagonal averaged over the outputs.
    let byM0 = 0;
    for (const [dof, moment] of rows[0] ?? []) if (moment * moment > 1e-15) byM0 += m.dof_M0[dof] / (moment * moment);
    const zeta = dampratios.length === m.nactuator ? dampratios[a] : null;
    // Only for a damping ratio: J·M⁻¹·Jᵀ over the outputs, then its inverse.
    let operational = null;
    if (zeta !== null && outs > 0) {
      const dense = (row) => {
        const v = new Array(nv).fill(0);
        for (const [dof, moment] of row) v[dof] = moment;
        return v;
      };
      const solved = rows.map((row) => solveM(dense(row)));
      const A = rows.map((ri) => solved.map((xj) => ri.reduce((sum, [dof, moment]) => sum + moment * xj[dof], 0)));
      const lambda = invert(A.flat(), outs);
      if (lambda && lambda.every(Number.isFinite)) {
        operational = 0;
        for (let k = 0; k < outs; ++k) operational += lambda[k * outs + k] / outs;
      }
    }
    const osExcluded = treeTainted.has(jointTrn ? m.body_rootid[m.jnt_bodyid[target]] : -1);
    // A tendon's moment per joint (a fixed tendon's joints are single-dof: dof = joint's dofadr).
    const dofJoint = (dof) => { for (let j = m.njnt - 1; j >= 0; --j) if (m.jnt_dofadr[j] <= dof) return j; return -1; };
    actuators.push({
      index: a,
      name: name(O.mjOBJ_ACTUATOR, a),
      transmission: trnNames[trn] ?? String(trn),
      joint: jointTrn ? target : null,
      tendon: trn === 3 ? name('tendon', target) : null,
      moments: trn === 3 ? (rows[0] ?? []).map(([dof, moment]) => [dofJoint(dof), moment]) : null,
      length0: m.actuator_length0[a],
      gear: m.actuator_gear[6 * out],
      gaintype: m.actuator_gaintype[a],
      biastype: m.actuator_biastype[a],
      gainprm: prm(m.actuator_gainprm, 10),
      biasprm: kvExcluded ? null : prm(m.actuator_biasprm, 10),
      forcelimited: flag('ACTUATOR', a, 'actuator_forcelimited'),
      forcerange: [m.actuator_forcerange[2 * a], m.actuator_forcerange[2 * a + 1]],
      ctrllimited: flag('ACTUATOR', a, 'actuator_ctrllimited'),
      ctrlrange: [m.actuator_ctrlrange[2 * ctrl], m.actuator_ctrlrange[2 * ctrl + 1]],
      kv_excluded: kvExcluded ? 'the joint moves a body that takes its mass from a stand-in mesh' : null,
      reflected_inertia_m0: kvExcluded ? null : byM0,
      reflected_inertia_operational: osExcluded ? null : operational,
      // MuJoCo 3.15's kv for the same damping ratio: 2·ζ·√(kp·(J M⁻¹ Jᵀ)⁻¹).
      dampratio: zeta,
      kv_operational: zeta !== null && !osExcluded && operational !== null ? 2 * zeta * Math.sqrt(m.actuator_gainprm[10 * a] * operational) : null,
    });
  }
  const equalities = [];
  for (let e = 0; e < m.neq; ++e) {
    if (m.eq_type[e] !== 2) continue;  // mjEQ_JOINT
    equalities.push({
      index: e,
      joint1: m.eq_obj1id[e],
      joint2: m.eq_obj2id[e],  // -1: none
      active: flag('EQUALITY', e, 'eq_active0'),
      polycoef: Array.from(m.eq_data.slice(11 * e, 11 * e + 5)),
    });
  }
  d.delete();
  m.delete();
  return { model: modelPath, error: null, standins, guessed_inertia_bodies: guessedBodies, joints, actuators, equalities };
}

const out = { mujoco: mj.mj_versionString(), models: [] };
for (const model of models) {
  try {
    out.models.push(compile(model));
  } catch (err) {
    out.models.push({ model, error: describe(err) });
  }
}
process.stdout.write(JSON.stringify(out, null, 1) + '\n');
