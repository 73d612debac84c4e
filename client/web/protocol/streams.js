// Field encodings of the wire protocol (protocol/SPEC.md "Byte order and field types"), as
// protocol/streams.hpp writes and reads them: little-endian integers and floats, texts as a u16
// byte count then UTF-8, blobs as a u32 count then bytes, lists as a u16 count. Every read
// checks what is left before it takes anything; every limit is checked on both sides.

export class ProtocolError extends Error {
  constructor(reason) {
    super(reason);
    this.name = 'ProtocolError';
  }
}

const utf8 = new TextEncoder();
const fromUtf8 = new TextDecoder('utf-8');  // as the C++ reader: any bytes but control bytes

export class WriteStream {
  static reading = false;
  constructor() {
    this.bytes = new Uint8Array(256);
    this.length = 0;
  }
  reserve(n) {
    if (this.length + n <= this.bytes.length) return;
    const grown = new Uint8Array(Math.max(this.bytes.length * 2, this.length + n));
    grown.set(this.bytes.subarray(0, this.length));
    this.bytes = grown;
  }
  put(value, size) {
    this.reserve(size);
    let v = BigInt(value);
    for (let i = 0; i < size; ++i, v >>= 8n) this.bytes[this.length++] = Number(v & 0xffn);
  }
  u8(v) { this.put(v, 1); return v; }
  u16(v) { this.put(v, 2); return v; }
  u32(v) { this.put(v, 4); return v; }
  u64(v) { this.put(v, 8); return v; }
  f32(v) {
    this.reserve(4);
    new DataView(this.bytes.buffer).setFloat32(this.length, v, true);
    this.length += 4;
    return v;
  }
  vec3(v) { for (const c of v) this.f32(c); return v; }
  counted(data, max, width) {
    if (data.length > max) throw new ProtocolError(`field of ${data.length} bytes exceeds its limit of ${max}`);
    this.put(data.length, width);
    this.reserve(data.length);
    this.bytes.set(data, this.length);
    this.length += data.length;
  }
  text(v, max) { this.counted(utf8.encode(v), max, 2); return v; }
  blob(v, max) { this.counted(v, max, 4); return v; }
  hash(v) {
    if (v.length !== 32) throw new ProtocolError('a hash is 32 bytes');
    this.reserve(32);
    this.bytes.set(v, this.length);
    this.length += 32;
    return v;
  }
  count(n, max, what) {
    if (n > max) throw new ProtocolError(`too many ${what}: ${n} > ${max}`);
    this.u16(n);
    return n;
  }
  result() { return this.bytes.slice(0, this.length); }
}

export class ReadStream {
  static reading = true;
  constructor(bytes) {
    this.bytes = bytes;
    this.view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    this.at = 0;
  }
  need(n) {
    const left = this.bytes.length - this.at;
    if (left < n) throw new ProtocolError(`message truncated: needs ${n} more bytes, has ${left}`);
  }
  get(size) {
    this.need(size);
    let v = 0n;
    for (let i = size - 1; i >= 0; --i) v = (v << 8n) | BigInt(this.bytes[this.at + i]);
    this.at += size;
    return v;
  }
  u8() { return Number(this.get(1)); }
  u16() { return Number(this.get(2)); }
  u32() { return Number(this.get(4)); }
  u64() { return this.get(8); }
  f32() {
    this.need(4);
    const v = this.view.getFloat32(this.at, true);
    this.at += 4;
    if (!Number.isFinite(v)) throw new ProtocolError('a float field is not finite');
    return v;
  }
  vec3() { return [this.f32(), this.f32(), this.f32()]; }
  text(_, max) {
    const size = this.u16();
    if (size > max) throw new ProtocolError(`text of ${size} bytes exceeds its limit of ${max}`);
    this.need(size);
    const raw = this.bytes.subarray(this.at, this.at + size);
    this.at += size;
    // Texts are names, parameters and reasons: never control bytes.
    for (const c of raw) if (c < 0x20 || c === 0x7f) throw new ProtocolError('text field holds a control byte');
    return fromUtf8.decode(raw);
  }
  blob(_, max) {
    const size = this.u32();
    if (size > max) throw new ProtocolError(`blob of ${size} bytes exceeds its limit of ${max}`);
    this.need(size);
    const v = this.bytes.slice(this.at, this.at + size);
    this.at += size;
    return v;
  }
  hash() {
    this.need(32);
    const v = this.bytes.slice(this.at, this.at + 32);
    this.at += 32;
    return v;
  }
  count(_, max, what) {
    const n = this.u16();
    if (n > max) throw new ProtocolError(`too many ${what}: ${n} > ${max}`);
    return n;
  }
  finish() {
    const left = this.bytes.length - this.at;
    if (left !== 0) throw new ProtocolError(`message has ${left} trailing bytes`);
  }
}
