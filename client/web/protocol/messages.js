// Every message of the Inkwire wire protocol (protocol/SPEC.md), mirroring protocol/messages.cpp
// function by function: one serialise function per message reads (with the same validation),
// writes and so measures it. Field names are the C++ ones. Numbers are JS numbers, except u64
// nonces (BigInt); vectors are arrays; hashes and blobs are Uint8Arrays.
import { ProtocolError, ReadStream, WriteStream } from './streams.js';

export const kMagic = 0x574b4e49;  // the bytes "INKW" read as a little-endian u32
export const kVersion = 9;
export const kMaxName = 64;
export const kMaxToken = 128;
export const kMaxReason = 512;
export const kMaxRenderer = 128;
export const kMaxSetting = 300;
export const kMaxSettings = 64;
export const kMaxAssets = 1024;
export const kMaxProductSamples = 360;
export const kMaxZoomLevels = 3;
export const kMaxChunk = 64 * 1024;
export const kMaxTween = 16 * 1024;
export const kMaxAssetBytes = 2 ** 30;
export const kMaxCropBytes = 64 * 1024;
export const kMaxVideoFrameBytes = 64 * 1024;
export const kMaxVideoSide = 320;
export const kMaxPhotoBytes = 120 * 1024;
export const kMaxVoiceBytes = 1275;
export const kMaxMembers = 64;
export const kVoiceTicketChars = 32;
export const kHostKeyChars = 32;
export const kMaxPoseDegrees = 90;
export const kMaxEyeOpenness = 200;

export const MessageType = Object.freeze({
  hello: 1, welcome: 2, error: 3, ping: 4, pong: 5, join: 6, leave: 7, snapshot: 8, 'style-change': 9, 'camera-pose': 10,
  'object-pose': 11, 'expression-code': 12, 'tween-data': 13, 'asset-announce': 14, 'asset-request': 15, 'asset-chunk': 16,
  publish: 17, 'neutral-photo': 18, 'face-crop': 19, 'face-region': 20, 'voice-frame': 21, 'member-face': 22, roster: 23,
  permissions: 24, 'face-video': 25, 'key-frame-request': 26, 'voice-route': 27, 'host-key': 28, 'room-control': 29,
  'member-layers': 30,
});
export const kMessageTypes = 30;
export const RoomAction = Object.freeze({ lock: 1, unlock: 2, remove: 3 });
export const FaceSource = Object.freeze({ neutral: 0, camera: 1, voice: 2 });
export const nameOf = (type) => Object.keys(MessageType).find((k) => MessageType[k] === type) ?? 'unknown';

export const SessionKind = Object.freeze({ scene: 1, turntable: 2, conference: 3 });
export const AssetKind = Object.freeze({ mesh: 1, image: 2, samples: 3, tween: 4, landmarks: 5, matte: 6, zoom: 7 });
export const kAssetKinds = 7;
export const ErrorCode = Object.freeze({
  'bad-version': 1, malformed: 2, 'no-session': 3, 'bad-token': 4, 'not-joined': 5, 'no-asset': 6, 'too-slow': 7,
  'shutting-down': 8, refused: 9, 'not-allowed': 10, locked: 11, removed: 12,
});

function check(ok, reason) {
  if (!ok) throw new ProtocolError(reason);
}

function enumeration(s, value, first, last, what, size) {
  const v = size === 1 ? s.u8(value) : s.u16(value);
  if (s.constructor.reading && (v < first || v > last)) throw new ProtocolError(`unknown ${what} ${v}`);
  return v;
}

// Names (sessions, renderers, setting keys) are plain: letters, digits and the extra characters.
function plain(text, extra) {
  for (const c of text) if (!/[A-Za-z0-9]/.test(c) && !extra.includes(c)) return false;
  return true;
}

const length = (v) => Math.hypot(...v);
const sub = (a, b) => a.map((x, i) => x - b[i]);

function serialiseHello(s, m) {
  m.magic = s.u32(m.magic ?? kMagic);
  m.version = s.u16(m.version ?? kVersion);
  m.client_name = s.text(m.client_name ?? '', kMaxName);
}

function serialiseWelcome(s, m) {
  m.version = s.u16(m.version ?? kVersion);
  m.server_name = s.text(m.server_name ?? '', kMaxName);
}

function serialiseErrorMessage(s, m) {
  m.code = enumeration(s, m.code ?? 9, 1, 12, 'error code', 2);
  m.reason = s.text(m.reason ?? '', kMaxReason);
}

function serialisePing(s, m) { m.nonce = s.u64(m.nonce ?? 0n); }
function serialisePong(s, m) { m.nonce = s.u64(m.nonce ?? 0n); }

function serialiseJoin(s, m) {
  m.session = s.text(m.session ?? '', kMaxName);
  m.token = s.text(m.token ?? '', kMaxToken);
  m.open_room = flag(s, m.open_room, 'join open room');
  if (s.constructor.reading) check(m.session.length > 0 && plain(m.session, '-_.'), 'session name must be letters, digits, - _ .');
}

function serialiseLeave() {}

function serialiseStyleChange(s, m) {
  m.renderer = s.text(m.renderer ?? 'default', kMaxRenderer);
  const settings = m.settings ?? [];
  const n = s.count(settings.length, kMaxSettings, 'style settings');
  m.settings = [];
  for (let i = 0; i < n; ++i) {
    const setting = s.text(settings[i], kMaxSetting);
    if (s.constructor.reading) {
      const eq = setting.indexOf('=');
      check(eq > 0 && plain(setting.slice(0, eq), '_-'), 'style setting is not KEY=VALUE');
    }
    m.settings.push(setting);
  }
  if (s.constructor.reading) check(m.renderer.length > 0 && plain(m.renderer, '-_+'), 'renderer name must be letters, digits, - _ +');
}

function serialiseCameraPose(s, m) {
  m.sequence = s.u32(m.sequence ?? 0);
  m.position = s.vec3(m.position ?? [0, 0, 5]);
  m.target = s.vec3(m.target ?? [0, 0, 0]);
  m.up = s.vec3(m.up ?? [0, 1, 0]);
  m.fov_y_degrees = s.f32(m.fov_y_degrees ?? 45);
  if (s.constructor.reading) {
    check(m.fov_y_degrees >= 1 && m.fov_y_degrees <= 170, 'camera field of view outside 1..170 degrees');
    check(length(m.up) > 1e-6, 'camera up vector is zero');
    check(length(sub(m.position, m.target)) > 1e-6, 'camera position equals its target');
    check(length(m.position) < 1e6 && length(m.target) < 1e6, 'camera outside the +-1e6 world');
  }
}

function serialiseObjectPose(s, m) {
  m.sequence = s.u32(m.sequence ?? 0);
  m.rotation = [0, 1, 2, 3].map((i) => s.f32((m.rotation ?? [0, 0, 0, 1])[i]));
  m.translation = s.vec3(m.translation ?? [0, 0, 0]);
  m.scale = s.f32(m.scale ?? 1);
  if (s.constructor.reading) {
    check(Math.abs(length(m.rotation) - 1) < 1e-3, 'object rotation is not a unit quaternion');
    check(m.scale > 1e-6 && m.scale < 1e6, 'object scale outside 1e-6..1e6');
    check(length(m.translation) < 1e6, 'object outside the +-1e6 world');
  }
}

function serialiseExpressionCode(s, m) {
  m.code = s.u8(m.code ?? 0);
  m.intensity = s.u8(m.intensity ?? 0);
  m.sequence = s.u16(m.sequence ?? 0);
  m.params = [0, 1, 2, 3].map((i) => {
    const raw = s.u8(((m.params ?? [0, 0, 0, 0])[i] + 256) % 256);
    return raw > 127 ? raw - 256 : raw;
  });
}

function serialiseTweenData(s, m) {
  m.pair = s.u16(m.pair ?? 0);
  m.data = s.blob(m.data ?? new Uint8Array(), kMaxTween);
}

function serialiseAssetAnnounce(s, m) {
  m.hash = s.hash(m.hash ?? new Uint8Array(32));
  m.size = Number(s.u64(m.size ?? 0));
  m.kind = enumeration(s, m.kind ?? 1, 1, kAssetKinds, 'asset kind', 1);
  m.name = s.text(m.name ?? '', kMaxName);
  if (s.constructor.reading) {
    check(m.size <= kMaxAssetBytes, 'asset larger than 1 GiB');
    check(m.name.length > 0 && m.name[0] !== '.' && plain(m.name, '-_.'), 'asset name must be a plain file name');
  }
}

function serialiseAssetRequest(s, m) {
  m.hash = s.hash(m.hash ?? new Uint8Array(32));
  m.offset = Number(s.u64(m.offset ?? 0));
  m.length = s.u32(m.length ?? 0);
  if (s.constructor.reading) check(m.length > 0 && m.length <= kMaxChunk && m.offset <= kMaxAssetBytes, 'asset request outside 1..65536 bytes');
}

function serialiseAssetChunk(s, m) {
  m.hash = s.hash(m.hash ?? new Uint8Array(32));
  m.offset = Number(s.u64(m.offset ?? 0));
  m.data = s.blob(m.data ?? new Uint8Array(), kMaxChunk);
  if (s.constructor.reading) check(m.offset + m.data.length <= kMaxAssetBytes, 'asset chunk beyond 1 GiB');
}

function serialiseProduct(s, m) {
  m.width = s.u16(m.width ?? 0);
  m.height = s.u16(m.height ?? 0);
  const directions = m.directions ?? [];
  const n = s.count(directions.length, kMaxProductSamples, 'product samples');
  m.directions = [];
  for (let i = 0; i < n; ++i) {
    // Unit vectors as 3 x i16 (component x 32767), as in the tween data's header.
    const d = (directions[i] ?? [0, 0, 0]).map((c) => {
      const q = s.u16((Math.round(Math.min(1, Math.max(-1, c)) * 32767) + 65536) % 65536);
      return Math.max(-1, (q > 32767 ? q - 65536 : q) / 32767);  // -32768 reads as -1, as in the C++ codec
    });
    if (s.constructor.reading) check(Math.abs(length(d) - 1) < 0.01, 'product sample direction is not a unit vector');
    m.directions.push(d);
  }
  m.cells = s.u16(m.cells ?? 0);
  m.distance_diagonals = s.f32(m.distance_diagonals ?? 1.4);
  m.fov_y_degrees = s.f32(m.fov_y_degrees ?? 45);
  const levels = m.levels ?? [];
  const nLevels = s.count(levels.length, kMaxZoomLevels, 'zoom levels');
  m.levels = [];
  for (let i = 0; i < nLevels; ++i) m.levels.push({ width: s.u16(levels[i]?.width ?? 0), height: s.u16(levels[i]?.height ?? 0) });
  if (s.constructor.reading) {
    const empty = m.directions.length === 0;
    let below = { width: m.width, height: m.height };
    for (const level of m.levels) {
      check(!empty && level.width > below.width && level.height > below.height && level.width <= 4095 && level.height <= 4095,
            'a zoom level is not larger than the one below it, or over 4095');
      below = level;
    }
    check(empty ? m.width === 0 && m.height === 0 && m.cells === 0 : m.directions.length >= 2, 'product with fewer than 2 samples');
    check(empty || (m.width >= 1 && m.height >= 1 && m.width <= 4095 && m.height <= 4095), 'product image size outside 1..4095');
    check(m.cells <= 4 * kMaxProductSamples, 'product has too many tween cells');
    check(m.distance_diagonals > 0.01 && m.distance_diagonals < 1000, 'product camera distance outside 0.01..1000 diagonals');
    check(m.fov_y_degrees >= 1 && m.fov_y_degrees <= 170, 'product field of view outside 1..170 degrees');
  }
}

function serialiseSnapshot(s, m) {
  m.session = s.text(m.session ?? '', kMaxName);
  m.kind = enumeration(s, m.kind ?? 1, 1, 3, 'session kind', 1);
  m.revision = s.u32(m.revision ?? 0);
  const assets = m.assets ?? [];
  const n = s.count(assets.length, kMaxAssets, 'assets');
  m.assets = [];
  for (let i = 0; i < n; ++i) {
    const a = { ...(assets[i] ?? {}) };
    serialiseAssetAnnounce(s, a);
    m.assets.push(a);
  }
  for (const [field, serialise] of [['style', serialiseStyleChange], ['camera', serialiseCameraPose], ['object', serialiseObjectPose],
                                    ['expression', serialiseExpressionCode], ['product', serialiseProduct]]) {
    m[field] = { ...(m[field] ?? {}) };
    serialise(s, m[field]);
  }
}

function flag(s, v, what) {
  const raw = s.u8(v ? 1 : 0);
  if (s.constructor.reading) check(raw <= 1, `${what} is not 0 or 1`);
  return raw === 1;
}

const int8 = (s, v) => {
  const raw = s.u8(((v ?? 0) + 256) % 256);
  return raw > 127 ? raw - 256 : raw;
};

function serialisePublish(s, m) {
  m.camera = flag(s, m.camera, 'publish camera');
  m.microphone = flag(s, m.microphone, 'publish microphone');
}

function serialiseNeutralPhoto(s, m) {
  m.jpeg = s.blob(m.jpeg ?? new Uint8Array(), kMaxPhotoBytes);
}

function serialiseFaceCrop(s, m) {
  m.time_ms = s.u32(m.time_ms ?? 0);
  for (const f of ['frame_width', 'frame_height', 'x', 'y', 'width', 'height']) m[f] = s.u16(m[f] ?? 0);
  m.jpeg = s.blob(m.jpeg ?? new Uint8Array(), kMaxCropBytes);
  if (s.constructor.reading) {
    check(m.frame_width >= 16 && m.frame_height >= 16 && m.frame_width <= 4096 && m.frame_height <= 4096, 'face crop: frame size outside 16..4096');
    check(m.width >= 8 && m.height >= 8 && m.x + m.width <= m.frame_width && m.y + m.height <= m.frame_height, 'face crop: rectangle outside its frame');
  }
}

function serialiseFaceVideo(s, m) {
  m.time_ms = s.u32(m.time_ms ?? 0);
  m.sequence = s.u32(m.sequence ?? 0);
  for (const f of ['frame_width', 'frame_height', 'x', 'y', 'width', 'height']) m[f] = s.u16(m[f] ?? 0);
  m.key = flag(s, m.key, 'face video key');
  m.vp8 = s.blob(m.vp8 ?? new Uint8Array(), kMaxVideoFrameBytes);
  if (s.constructor.reading) {
    check(m.frame_width >= 16 && m.frame_height >= 16 && m.frame_width <= 4096 && m.frame_height <= 4096, 'face video: frame size outside 16..4096');
    check(m.width >= 8 && m.height >= 8 && m.x + m.width <= m.frame_width && m.y + m.height <= m.frame_height, 'face video: rectangle outside its frame');
    check(m.vp8.length > 0, 'empty face video frame');
  }
}

function serialiseKeyFrameRequest() {}

function serialiseVoiceRoute(s, m) {
  m.ticket = s.text(m.ticket ?? '', kVoiceTicketChars);
  if (s.constructor.reading) check(/^[0-9a-f]{32}$/.test(m.ticket), 'voice route: the ticket is not 32 hex digits');
}

function serialiseFaceRegion(s, m) {
  m.found = flag(s, m.found, 'face region found');
  for (const f of ['x', 'y', 'width', 'height']) m[f] = s.u16(m[f] ?? 0);
}

function serialiseVoiceFrame(s, m) {
  m.member = s.u16(m.member ?? 0);
  m.time_ms = s.u32(m.time_ms ?? 0);
  m.opus = s.blob(m.opus ?? new Uint8Array(), kMaxVoiceBytes);
  if (s.constructor.reading) check(m.opus.length > 0, 'empty voice frame');
}

function serialiseMemberFace(s, m) {
  m.member = s.u16(m.member ?? 0);
  m.time_ms = s.u32(m.time_ms ?? 0);
  // The code and its intensity only (as the C++ codec: a call's faces carry no sequence or params).
  m.expression = { code: s.u8(m.expression?.code ?? 0), intensity: s.u8(m.expression?.intensity ?? 0) };
  for (const f of ['yaw', 'pitch', 'roll']) m[f] = int8(s, m[f]);
  m.source = enumeration(s, m.source ?? 0, 0, 2, 'face source', 1);
}

// A layer's code and intensity: only codes that layer takes (common/face/expression.hpp): the
// expression layer 0-5 (neutral .. sad), the mouth layer those and the visemes 9-12.
const expressionLayerTakes = (code) => code <= 5;
const mouthLayerTakes = (code) => code <= 5 || (code >= 9 && code <= 12);
function layer(s, v, takes, what) {
  const out = { code: s.u8(v?.code ?? 0), intensity: s.u8(v?.intensity ?? 0) };
  if (s.constructor.reading) check(takes(out.code), `${what} code ${out.code} is not one that layer takes`);
  return out;
}

function serialiseMemberLayers(s, m) {
  m.member = s.u16(m.member ?? 0);
  m.time_ms = s.u32(m.time_ms ?? 0);
  for (const f of ['yaw', 'pitch', 'roll']) {
    m[f] = int8(s, m[f]);
    if (s.constructor.reading) check(Math.abs(m[f]) <= kMaxPoseDegrees, 'member layers: head pose outside +-90 degrees');
  }
  m.expression = layer(s, m.expression, expressionLayerTakes, 'member layers: expression');
  m.mouth = layer(s, m.mouth, mouthLayerTakes, 'member layers: mouth');
  m.eye_left = s.u8(m.eye_left ?? 100);
  m.eye_right = s.u8(m.eye_right ?? 100);
  if (s.constructor.reading) check(m.eye_left <= kMaxEyeOpenness && m.eye_right <= kMaxEyeOpenness, 'member layers: eye openness over 200%');
  m.source = enumeration(s, m.source ?? 0, 0, 2, 'face source', 1);
}

function serialiseCallMember(s, m) {
  m.member = s.u16(m.member ?? 0);
  m.name = s.text(m.name ?? '', kMaxName);
  for (const f of ['camera', 'microphone', 'speaking']) m[f] = flag(s, m[f], `member ${f}`);
  m.face_found = flag(s, m.face_found ?? true, 'member face found');
  const assets = m.assets ?? [];
  const n = s.count(assets.length, 2, 'member assets');
  m.assets = [];
  for (let i = 0; i < n; ++i) {
    const a = { ...(assets[i] ?? {}) };
    serialiseAssetAnnounce(s, a);
    m.assets.push(a);
  }
  if (s.constructor.reading) check(m.member !== 0, 'member number 0');
}

function serialiseRoster(s, m) {
  m.you = s.u16(m.you ?? 0);
  const members = m.members ?? [];
  const n = s.count(members.length, kMaxMembers, 'call members');
  m.members = [];
  for (let i = 0; i < n; ++i) {
    const member = { ...(members[i] ?? {}) };
    serialiseCallMember(s, member);
    m.members.push(member);
  }
  m.host = s.u16(m.host ?? 0);
  m.locked = flag(s, m.locked, 'roster locked');
}

function serialiseHostKey(s, m) {
  m.key = s.text(m.key ?? '', kHostKeyChars);
  if (s.constructor.reading) check(/^[0-9a-f]{32}$/.test(m.key), 'host key is not 32 hex digits');
}

function serialiseRoomControl(s, m) {
  m.action = enumeration(s, m.action ?? RoomAction.lock, 1, 3, 'room action', 1);
  m.member = s.u16(m.member ?? 0);
  if (s.constructor.reading) check(m.action === RoomAction.remove ? m.member !== 0 : m.member === 0, 'room control names a member only to remove');
}

// The changes the server will refuse this member: [{change: 'camera-pose', reason}], by name.
function serialisePermissions(s, m) {
  const refused = m.refused ?? [];
  const n = s.count(refused.length, 4, 'refused changes');
  m.refused = [];
  for (let i = 0; i < n; ++i) {
    const change = enumeration(s, MessageType[refused[i]?.change] ?? 0, MessageType['style-change'], MessageType['expression-code'],
                               'refused change', 2);
    m.refused.push({ change: nameOf(change), reason: s.text(refused[i]?.reason ?? '', kMaxReason) });
  }
}

// In MessageType order: index + 1 == type code.
const serialisers = [serialiseHello, serialiseWelcome, serialiseErrorMessage, serialisePing, serialisePong, serialiseJoin, serialiseLeave,
                     serialiseSnapshot, serialiseStyleChange, serialiseCameraPose, serialiseObjectPose, serialiseExpressionCode,
                     serialiseTweenData, serialiseAssetAnnounce, serialiseAssetRequest, serialiseAssetChunk, serialisePublish,
                     serialiseNeutralPhoto, serialiseFaceCrop, serialiseFaceRegion, serialiseVoiceFrame, serialiseMemberFace, serialiseRoster,
                     serialisePermissions, serialiseFaceVideo, serialiseKeyFrameRequest, serialiseVoiceRoute, serialiseHostKey,
                     serialiseRoomControl, serialiseMemberLayers];

export const kHeaderBytes = 6;
export const kMaxPayload = 128 * 1024;

// The whole frame of `message` ({type: 'snapshot', ...fields}): u32 payload length, u16 type,
// payload. Throws ProtocolError if a field exceeds its limit.
export function encode(message) {
  const type = MessageType[message.type];
  if (!type) throw new ProtocolError(`unknown message type ${message.type}`);
  const s = new WriteStream();
  s.u32(0);
  s.u16(type);
  serialisers[type - 1](s, { ...message });
  const frame = s.result();
  const payload = frame.length - kHeaderBytes;
  if (payload > kMaxPayload) throw new ProtocolError(`${message.type} message exceeds the frame limit`);
  new DataView(frame.buffer).setUint32(0, payload, true);
  return frame;
}

// Reads a frame header; throws ProtocolError for an unknown type or a length over the limit,
// before anything of the payload is read.
export function parseHeader(bytes) {
  const view = new DataView(bytes.buffer, bytes.byteOffset, kHeaderBytes);
  const length = view.getUint32(0, true), type = view.getUint16(4, true);
  if (type < 1 || type > kMessageTypes) throw new ProtocolError(`unknown message type ${type}`);
  if (length > kMaxPayload) throw new ProtocolError(`frame of ${length} bytes exceeds the limit of ${kMaxPayload}`);
  return { length, type };
}

// One payload of `type`; throws ProtocolError on any malformed, out-of-range or trailing byte.
export function decode(type, payload) {
  if (type < 1 || type > kMessageTypes) throw new ProtocolError(`unknown message type ${type}`);
  if (payload.length > kMaxPayload) throw new ProtocolError('payload exceeds the frame limit');
  const s = new ReadStream(payload);
  const m = { type: nameOf(type) };
  serialisers[type - 1](s, m);
  s.finish();
  return m;
}

// Frames out of a byte stream in arbitrary pieces (a streamed fetch body), as C++'s
// FrameDecoder: feed() what arrived, then next() until it returns null. A header over the limit
// throws at once, before its payload is waited for.
export class FrameReader {
  constructor() {
    this.pending = new Uint8Array(0);
  }
  feed(bytes) {
    const joined = new Uint8Array(this.pending.length + bytes.length);
    joined.set(this.pending);
    joined.set(bytes, this.pending.length);
    this.pending = joined;
  }
  next() {
    if (this.pending.length < kHeaderBytes) return null;
    const { length, type } = parseHeader(this.pending);
    if (this.pending.length < kHeaderBytes + length) return null;
    const m = decode(type, this.pending.subarray(kHeaderBytes, kHeaderBytes + length));
    this.pending = this.pending.slice(kHeaderBytes + length);
    return m;
  }
}

// A whole frame (as one WebSocket message carries it): exactly one message, nothing after it.
export function decodeFrame(frame) {
  if (frame.length < kHeaderBytes) throw new ProtocolError(`frame of ${frame.length} bytes is shorter than its header`);
  const { length, type } = parseHeader(frame);
  if (frame.length !== kHeaderBytes + length) throw new ProtocolError(`frame says ${length} bytes of payload, has ${frame.length - kHeaderBytes}`);
  return decode(type, frame.subarray(kHeaderBytes));
}
