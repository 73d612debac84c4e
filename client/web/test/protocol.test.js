// The web client's codec against the C++ one: it decodes the C++ golden frames
// (tests/golden/protocol-frames.json, written by ProtocolTest) and writes the same bytes back;
// it refuses every truncation, lengths over their limits, unknown types and random bytes with
// a ProtocolError, never anything else. Run: node --test client/web/test/
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { test } from 'node:test';

import { decodeTweenCell, encodeTweenCell, TweenError } from '../common/tween_data.js';
import { decode, decodeFrame, encode, FrameReader, kHeaderBytes, kMaxPayload, kMessageTypes, kVersion, MessageType, parseHeader } from '../protocol/messages.js';
import { ProtocolError } from '../protocol/streams.js';

const golden = JSON.parse(readFileSync(new URL('../../../tests/golden/protocol-frames.json', import.meta.url)));
const fromHex = (hex) => Uint8Array.from(hex.match(/../g).map((b) => parseInt(b, 16)));
const toHex = (bytes) => Array.from(bytes, (b) => b.toString(16).padStart(2, '0')).join('');

test('the golden frames are of this version and cover every message type', () => {
  assert.equal(golden.version, kVersion);
  assert.deepEqual(golden.frames.map((f) => MessageType[f.type]), Array.from({ length: kMessageTypes }, (_, i) => i + 1));
});

test('every C++ frame decodes and encodes back to the same bytes', () => {
  for (const { type, hex } of golden.frames) {
    const message = decodeFrame(fromHex(hex));
    assert.equal(message.type, type);
    assert.equal(toHex(encode(message)), hex, type);
  }
});

test('decoded fields are the C++ ones', () => {
  const byType = Object.fromEntries(golden.frames.map((f) => [f.type, decodeFrame(fromHex(f.hex))]));
  assert.equal(byType.hello.client_name, 'viewer-1');
  assert.equal(byType.ping.nonce, 0x0123456789abcdefn);
  const s = byType.snapshot;
  assert.equal(s.session, 'demo');
  assert.equal(s.kind, 2);
  assert.equal(s.revision, 17);
  assert.equal(s.assets.length, 2);
  assert.equal(s.assets[0].name, 'cow.off');
  assert.equal(s.assets[0].size, 123456);
  assert.deepEqual(s.style.settings, ['boil_fps=6', 'paper=canvas']);
  assert.equal(s.product.width, 512);
  assert.equal(s.product.height, 384);
  assert.equal(s.product.cells, 4);
  assert.equal(s.product.directions.length, 4);
  assert.deepEqual(s.product.directions[1], [1, 0, 0]);
  assert.deepEqual(byType['expression-code'].params, [-127, 0, 5, 127]);
  assert.equal(byType['tween-data'].data.length, 800);
  // Calls.
  assert.deepEqual([byType.publish.camera, byType.publish.microphone], [true, false]);
  const crop = byType['face-crop'];
  assert.deepEqual([crop.time_ms, crop.frame_width, crop.frame_height, crop.x, crop.y, crop.width, crop.height, crop.jpeg.length],
                   [123456, 640, 480, 200, 100, 240, 260, 200]);
  assert.deepEqual([byType['voice-frame'].member, byType['voice-frame'].time_ms, byType['voice-frame'].opus.length], [3, 123440, 40]);
  const face = byType['member-face'];
  assert.deepEqual([face.member, face.yaw, face.pitch, face.roll, face.source, face.expression.code], [3, -20, 5, 127, 1, 3]);
  const layers = byType['member-layers'];
  assert.deepEqual([layers.member, layers.time_ms, layers.yaw, layers.pitch, layers.roll, layers.expression.code, layers.expression.intensity,
                    layers.mouth.code, layers.mouth.intensity, layers.eye_left, layers.eye_right, layers.source],
                   [3, 123456, -25, 12, 20, 1, 180, 10, 140, 35, 110, 1]);
  const roster = byType.roster;
  assert.equal(roster.you, 2);
  assert.deepEqual(roster.members.map((m) => [m.member, m.name, m.speaking, m.face_found, m.assets.length]),
                   [[2, 'Ada', false, true, 0], [3, 'Grace', true, false, 2]]);
  assert.equal(roster.members[1].assets[1].name, 'face.landmarks.json');
  assert.deepEqual(byType.permissions.refused.map((r) => r.change), ['style-change', 'camera-pose']);
  assert.match(byType.permissions.refused[1].reason, /editors may move the camera/);
});

test('a stream of frames in pieces of any size gives every frame once, in order (the voice route)', () => {
  const frames = golden.frames.map((f) => fromHex(f.hex));
  const stream = new Uint8Array(frames.reduce((n, f) => n + f.length, 0));
  frames.reduce((at, f) => (stream.set(f, at), at + f.length), 0);
  for (const piece of [1, 7, 100, stream.length]) {
    const reader = new FrameReader(), got = [];
    for (let at = 0; at < stream.length; at += piece) {
      reader.feed(stream.subarray(at, at + piece));
      for (let m; (m = reader.next()); ) got.push(m.type);
    }
    assert.deepEqual(got, golden.frames.map((f) => f.type), `pieces of ${piece} bytes`);
  }
  const over = new Uint8Array(kHeaderBytes);
  new DataView(over.buffer).setUint32(0, kMaxPayload + 1, true);
  new DataView(over.buffer).setUint16(4, 1, true);
  const reader = new FrameReader();
  reader.feed(over);
  assert.throws(() => reader.next(), ProtocolError, 'a header over the limit is refused before its payload comes');
});

test('every truncation of every frame is refused with a ProtocolError', () => {
  for (const { type, hex } of golden.frames) {
    const frame = fromHex(hex);
    for (let cut = 0; cut < frame.length; ++cut) assert.throws(() => decodeFrame(frame.subarray(0, cut)), ProtocolError, `${type} cut at ${cut}`);
    // And a payload cut short under a header that says so.
    const payload = frame.subarray(kHeaderBytes);
    for (let cut = 0; cut < payload.length; ++cut) assert.throws(() => decode(MessageType[type], payload.subarray(0, cut)), ProtocolError);
  }
});

test('trailing bytes, lengths over the limit and unknown types are refused', () => {
  const ping = fromHex(golden.frames.find((f) => f.type === 'ping').hex);
  const longer = new Uint8Array(ping.length + 1);
  longer.set(ping);
  assert.throws(() => decodeFrame(longer), ProtocolError);
  const header = new Uint8Array(kHeaderBytes);
  new DataView(header.buffer).setUint32(0, kMaxPayload + 1, true);
  new DataView(header.buffer).setUint16(4, 4, true);
  assert.throws(() => parseHeader(header), /exceeds the limit/);
  new DataView(header.buffer).setUint32(0, 8, true);
  for (const type of [0, kMessageTypes + 1, 65535]) {
    new DataView(header.buffer).setUint16(4, type, true);
    assert.throws(() => parseHeader(header), /unknown message type/);
  }
  assert.throws(() => encode({ type: 'join', session: 'x'.repeat(65), token: '' }), ProtocolError);
  assert.throws(() => encode({ type: 'tween-data', pair: 0, data: new Uint8Array(16 * 1024 + 1) }), ProtocolError);
});

test('values out of range are refused as the C++ reader refuses them', () => {
  const refuse = (message) => {
    const frame = encode(message);
    assert.throws(() => decodeFrame(frame), ProtocolError, JSON.stringify(message, (_, v) => (typeof v === 'bigint' ? String(v) : v)));
  };
  refuse({ type: 'camera-pose', position: [0, 0, 0], target: [0, 0, 0] });
  refuse({ type: 'camera-pose', fov_y_degrees: 0 });
  refuse({ type: 'object-pose', rotation: [2, 0, 0, 0] });
  refuse({ type: 'style-change', renderer: '../../etc', settings: [] });
  refuse({ type: 'style-change', renderer: 'comic', settings: ['no-equals-sign'] });
  refuse({ type: 'join', session: 'a b', token: '' });
  refuse({ type: 'asset-announce', size: 1, kind: 1, name: '../passwd' });
  refuse({ type: 'asset-request', length: 0 });
  refuse({ type: 'snapshot', session: 's', kind: 2, product: { width: 64, height: 64, directions: [[0, 0, 1]], cells: 0 } });
  refuse({ type: 'snapshot', session: 's', kind: 2, product: { width: 64, height: 64, directions: [[0, 0, 1], [0, 0, 0.5]], cells: 1 } });
  const jpeg = new Uint8Array([0xff, 0xd8, 0xff, 0xe0, 1, 2]);
  refuse({ type: 'face-crop', frame_width: 640, frame_height: 480, x: 600, y: 0, width: 64, height: 64, jpeg });
  refuse({ type: 'voice-frame', opus: new Uint8Array() });
  refuse({ type: 'member-face', source: 3 });
  // A face's pose within +-90 degrees, each layer's codes its own, eyes open at most 200% (as the C++ codec).
  refuse({ type: 'member-layers', yaw: 91 });
  refuse({ type: 'member-layers', roll: -128 });
  refuse({ type: 'member-layers', expression: { code: 7, intensity: 255 } });
  refuse({ type: 'member-layers', expression: { code: 10, intensity: 255 } });
  refuse({ type: 'member-layers', mouth: { code: 6, intensity: 255 } });
  refuse({ type: 'member-layers', mouth: { code: 13, intensity: 255 } });
  refuse({ type: 'member-layers', eye_left: 201 });
  refuse({ type: 'roster', members: [{ member: 0, name: 'x' }] });
  refuse({ type: 'permissions', refused: [{ change: 'snapshot', reason: 'x' }] });
  assert.throws(() => encode({ type: 'voice-frame', opus: new Uint8Array(1276) }), ProtocolError);
});

test('random bytes end in messages or a ProtocolError, never anything else', () => {
  let seed = 12345;  // printed on failure so it can be replayed
  const next = () => ((seed = (seed * 1103515245 + 12345) >>> 0) >>> 16) & 0xff;
  for (let i = 0; i < 20000; ++i) {
    const type = 1 + (i % kMessageTypes), length = next() % 96;
    const payload = Uint8Array.from({ length }, next);
    try {
      decode(type, payload);
    } catch (e) {
      assert.ok(e instanceof ProtocolError, `seed ${seed}: ${e}`);
    }
  }
});

test('the C++ tween cell decodes to the same points and encodes back to the same bytes', () => {
  const { width, height, samples, hex, points } = golden.cell;
  const cell = decodeTweenCell(fromHex(hex), width, height, samples);
  assert.deepEqual(cell.samples, [3, 4]);
  assert.deepEqual(cell.points, points);
  assert.equal(toHex(encodeTweenCell(cell, width, height, samples)), hex);
  // Against a product it does not belong to, cut short, or longer: refused with a reason.
  assert.throws(() => decodeTweenCell(fromHex(hex), width, height, 4), /out of range/);
  assert.throws(() => decodeTweenCell(fromHex(hex), 64, 64, samples), /outside the image/);
  const bytes = fromHex(hex);
  for (let cut = 0; cut < bytes.length; ++cut) assert.throws(() => decodeTweenCell(bytes.subarray(0, cut), width, height, samples), TweenError);
  assert.throws(() => decodeTweenCell(Uint8Array.from([...bytes, 0]), width, height, samples), /after the cell/);
});
