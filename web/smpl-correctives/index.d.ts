// Types of smpl-correctives (index.js). Shapes: K joints, P = 9(K-1) pose
// features, T driven targets (correctives entries, then basis targets).
import type { Object3D, SkinnedMesh } from 'three';

/** One `correctives` entry of the smpl-export metadata (docs/file-contract.md). */
export interface CorrectiveEntry {
  /** index n into the pose features f (0 .. P-1) */
  feature: number;
  /** morph target name, e.g. `pose_left_knee_12` */
  target: string;
  /** weight = scale * f[feature] + offset (default 1, 0) */
  scale?: number;
  offset?: number;
  /** "split" encoding: weight = max(0, scale * f[feature] + offset) */
  rectified?: boolean;
}

/** `corrective_basis` (exports with --corrective-basis K). */
export interface CorrectiveBasis {
  targets: string[];
  features: number;
  /** C, K x P, row-major (flat) */
  matrix: number[];
  scale: number[];
  offset: number[];
}

/** The smpl-export metadata: glTF `asset.extras.smpl` or the `<file>.smpl.json` sidecar. */
export interface SmplMetadata {
  model_kind?: 'smpl' | 'smplh' | 'smplx' | 'mano' | string;
  model_name?: string;
  joint_names?: string[];
  /** parent index per joint, -1 for the root */
  parents?: number[];
  /** --skeleton-names: 'mixamo' or 'ue5' (absent: the bones carry joint_names) */
  skeleton_names?: 'mixamo' | 'ue5' | string;
  /** the bone of each joint in the file (with skeleton_names); bones are found by these */
  bone_names?: string[];
  max_influences?: number;
  units?: string;
  up_axis?: string;
  corrective_encoding?: 'signed' | 'unit' | 'split' | string;
  correctives?: CorrectiveEntry[];
  corrective_basis?: CorrectiveBasis;
  morph_targets?: string[];
  [key: string]: unknown;
}

export interface BindOptions {
  /** where the one-time warnings go (default console.warn) */
  warn?: (message: string) => void;
}

export interface Correctives {
  /** the skinned meshes whose morphTargetInfluences are written */
  readonly meshes: SkinnedMesh[];
  /** f of the last update (P = 9(K-1)), dimensionless */
  readonly features: Float64Array;
  /** the T weights of the last update/rest, in targetNames order */
  readonly weights: Float64Array;
  /** the T driven target names */
  readonly targetNames: string[];
  /** false: update() writes nothing (the weights stay as they are) */
  enabled: boolean;
  /** Set the weights from the bones' current rotations; allocates nothing. Returns `weights`. */
  update(): Float64Array;
  /** Set the weights of the rest pose (f = 0): the body without pose correctives. */
  rest(): Float64Array;
  /** Compute f from the bones without writing weights. */
  computeFeatures(): Float64Array;
}

/**
 * Bind the correctives of every skinned mesh under `root`.
 * @throws Error when no skinned mesh carries a corrective target, a joint of
 *   the metadata has no bone, or the metadata's joint_names, parents,
 *   correctives or corrective_basis are malformed (the message names the field).
 */
export function bindCorrectives(root: Object3D, metadata: SmplMetadata | null, options?: BindOptions): Correctives;

/** The smpl-export metadata of a GLTFLoader result (asset.extras.smpl), or null. */
export function metadataFromGltf(gltf: { asset?: any; parser?: any; scene?: Object3D }): SmplMetadata | null;

/** Scale an FBXLoader group to metres by its UnitScaleFactor (cm per unit); returns the factor. */
export function applyFbxUnitScale(fbxGroup: Object3D): number;
