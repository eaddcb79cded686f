// The three.js side of `cargo xtask gltf-check`: loads each glTF file that
// rigtform-gltf-samples sampled (SAMPLES_JSON, argument 1) with three.js's
// GLTFLoader, checks that three.js read the same key times and values as
// rigtform's renderer did, evaluates each animation track's own interpolant
// (three.js's DiscreteInterpolant, LinearInterpolant and
// QuaternionLinearInterpolant, and the loader's GLTFCubicSplineInterpolant
// and GLTFCubicSplineQuaternionInterpolant, which its tracks' createInterpolant
// picks) at the same times, and compares with rigtform's samples.
//
// Prints per kind of channel the largest differences, then
//   three.js agreement: max rotation difference X rad, max translation difference Y over N samples of K channels
// (translations and scales together) and exits with status 1 if either is
// above 1e-6, or if three.js read different keys.

import { readFileSync } from 'node:fs';
import { dirname } from 'node:path';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';

const LIMIT = 1e-6;

// three.js's FileLoader reports progress with the browser's ProgressEvent,
// which node does not have; the loader only dispatches it.
globalThis.ProgressEvent ??= class ProgressEvent extends Event {
	constructor(type, init = {}) {
		super(type);
		Object.assign(this, init);
	}
};

/** The angle of the rotation between two quaternions (x, y, z, w), in f64:
 *  4 atan2(|a - b|, |a + b|) with b on a's side, accurate near 0 and pi. */
function rotationAngle(a, b) {
	const dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
	const s = dot < 0 ? -1 : 1;
	let minus = 0, plus = 0;
	for (let i = 0; i < 4; i++) {
		minus += (a[i] - s * b[i]) ** 2;
		plus += (a[i] + s * b[i]) ** 2;
	}
	return 4 * Math.atan2(Math.sqrt(minus), Math.sqrt(plus));
}

async function load(path) {
	const text = readFileSync(path, 'utf8');
	return new Promise((resolve, reject) =>
		new GLTFLoader().parse(text, dirname(path) + '/', resolve, reject));
}

const spec = JSON.parse(readFileSync(process.argv[2], 'utf8'));
let maxRotation = 0, maxTranslation = 0, samples = 0, channels = 0, failures = 0;
const byKind = new Map();

for (const file of spec.files) {
	const gltf = await load(file.path);
	for (const c of file.channels) {
		const clip = gltf.animations[c.animation];
		const track = clip && clip.tracks[c.track];
		if (!track) {
			console.error(`${file.path}: three.js has no track ${c.track} in animation ${c.animation}`);
			failures++;
			continue;
		}
		const size = c.path === 'rotation' ? 4 : 3;
		// The same keys: times and values as f32, bit for bit.
		const same = (a, b) => a.length === b.length && a.every((v, i) => Object.is(Math.fround(v), Math.fround(b[i])) || v === b[i]);
		if (!same(Array.from(track.times), c.times) || !same(Array.from(track.values), c.values)) {
			console.error(`${file.path}: animation ${c.animation} track ${c.track} (${track.name}): three.js read other keys than rigtform`);
			failures++;
			continue;
		}
		const interpolant = track.createInterpolant();
		const kind = `${c.path} ${c.interpolation} (${interpolant.constructor.name})`;
		const worst = byKind.get(kind) || { max: 0, n: 0, channels: 0 };
		worst.channels++;
		c.t.forEach((t, k) => {
			const got = Array.from(interpolant.evaluate(Math.fround(t)));
			// rigtform's f32s, written as the shortest decimals that read back as them.
			const want = c.samples.slice(size * k, size * k + size).map(Math.fround);
			let d;
			if (size === 4) {
				d = rotationAngle(got, want);
				maxRotation = Math.max(maxRotation, d);
			} else {
				d = Math.max(...got.map((v, i) => Math.abs(v - want[i])));
				maxTranslation = Math.max(maxTranslation, d);
			}
			if (!(d <= LIMIT)) {
				console.error(`${kind} at t = ${t}: three.js ${got}, rigtform ${want}, difference ${d}`);
			}
			worst.max = Math.max(worst.max, d);
			worst.n++;
			samples++;
		});
		byKind.set(kind, worst);
		channels++;
	}
}

for (const [kind, w] of [...byKind].sort()) {
	console.log(`  ${kind.padEnd(72)} ${String(w.channels).padStart(3)} channels, ${String(w.n).padStart(4)} samples, max difference ${w.max.toExponential(3)}`);
}
const line = `three.js agreement: max rotation difference ${maxRotation.toExponential(3)} rad, max translation difference ${maxTranslation.toExponential(3)} over ${samples} samples of ${channels} channels`;
console.log(line);
if (failures > 0 || !(maxRotation <= LIMIT) || !(maxTranslation <= LIMIT)) {
	console.error(`gltf-check failed: ${failures} channel(s) read differently, limit ${LIMIT}`);
	process.exit(1);
}
