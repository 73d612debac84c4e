// A call member's camera in the browser (SPEC F8, F17), as client/call/publisher.cpp sends it:
// the face as VP8 video (WebCodecs' VideoEncoder): 160 x 160 pictures of a rectangle that
// follows the region the server reports (followFace, the rule of client/call/face_crop.cpp,
// both pinned by tests/golden/warp-vectors.json), or the whole frame scaled to at most 320 px a side until it
// finds one, at most 15 a second, a key frame when the picture size changes, the rectangle
// jumps or the server asks. Where the engine has no VP8 encoder, JPEG crops as before
// (`format` says which). The neutral photo: the frame shown when it is taken. Pictures stay in
// memory.

export const kFaceVideoSide = 160, kFaceSearchWidth = 320;
const kPhotoSide = 480, kVideoBitrate = 36000, kMinAskedBitrate = 1000, kFaceVideoFps = 15;
const kJumpMove = 0.5, kJumpScale = 1.5;

function fit(width, height, side) {
  const scale = Math.min(1, side / width, side / height);
  return [Math.max(1, Math.round(width * scale)), Math.max(1, Math.round(height * scale))];
}

function draw(video, [sx, sy, sw, sh], [w, h]) {
  const canvas = new OffscreenCanvas(w, h);
  canvas.getContext('2d').drawImage(video, sx, sy, sw, sh, 0, 0, w, h);
  return canvas;
}

async function jpeg(video, rect, size, quality) {
  const blob = await draw(video, rect, size).convertToBlob({ type: 'image/jpeg', quality });
  return new Uint8Array(await blob.arrayBuffer());
}

// The neutral photo: the frame the preview shows now.
export function photoOf(video) {
  return jpeg(video, [0, 0, video.videoWidth, video.videoHeight], fit(video.videoWidth, video.videoHeight, kPhotoSide), 0.9);
}

// The square of the region's longer side about its centre, moved into the frame.
function squared(r, frameWidth, frameHeight) {
  const side = Math.min(Math.max(r.width, r.height), frameWidth, frameHeight);
  const clamp = (v, lo, hi) => Math.min(Math.max(v, lo), hi);
  const x = clamp(r.x + Math.trunc(r.width / 2) - Math.trunc(side / 2), 0, frameWidth - side);
  const y = clamp(r.y + Math.trunc(r.height / 2) - Math.trunc(side / 2), 0, frameHeight - side);
  return { found: true, x, y, width: side, height: side };
}

// The face video's picture while the face is not found, as client/call/face_crop.hpp's
// search_picture_size (pinned with it): the whole frame, neither side past kFaceSearchWidth,
// even sides of at least 16.
export function searchPictureSize(W, H) {
  const scale = Math.min(1, kFaceSearchWidth / Math.max(W, H)), even = (side) => Math.max(16, Math.round((side * scale) / 2) * 2);
  return [even(W), even(H)];
}

// The rectangle to show next: the region the server reported, square (the video's picture is,
// and a face stretched one way reads as another expression), and a jump (a key frame) when it
// went far from `shown` ({found: false}: the whole frame) or changed its size much.
export function followFace(shown, reportedRegion, frameWidth, frameHeight) {
  const reported = squared(reportedRegion, frameWidth, frameHeight);
  if (!shown.found) return { region: reported, jumped: true };
  const side = Math.max(1, Math.max(shown.width, shown.height));
  const dx = (reported.x + reported.width / 2) - (shown.x + shown.width / 2);
  const dy = (reported.y + reported.height / 2) - (shown.y + shown.height / 2);
  const move = Math.hypot(dx, dy) / side;
  const scale = Math.max(reported.width, reported.height) / side;
  const grown = Math.max(scale, 1 / Math.max(scale, 1e-6));
  return { region: reported, jumped: move > kJumpMove || grown > kJumpScale };
}

// Whether this engine encodes VP8 at the face video's size ('vp8'), else 'jpeg'.
export async function faceFormat() {
  if (typeof VideoEncoder === 'undefined') return 'jpeg';
  try {
    const { supported } = await VideoEncoder.isConfigSupported({ codec: 'vp8', width: kFaceVideoSide, height: kFaceVideoSide, bitrate: kVideoBitrate });
    return supported ? 'vp8' : 'jpeg';
  } catch {
    return 'jpeg';
  }
}

// The face as VP8: one VideoEncoder per picture size; each chunk goes out as a face-video with
// the rectangle and time of the picture it came from. The encoder is asked for kVideoBitrate; what
// it makes is measured and held to that: WebKitGTK 2.50's encoder spends the bit rate asked for on
// every picture as if each lasted a second (1084 bytes a picture asked for 10 kbit/s, 3904 for 36,
// at 15 a second), so when pictures come out larger than the rate allows, it is asked for less in
// proportion; and meanwhile a bucket of one second's bytes skips a picture while it is empty.
class FaceVideo {
  constructor(send) {
    this.send = send;
    this.budget = kVideoBitrate / 8;  // bytes it may send now
    this.budgetAt = performance.now();
    this.skipped = 0;
    this.asked = kVideoBitrate;              // the bit rate the encoder is asked for
    this.measured = { pictures: 0, bytes: 0 };  // delta pictures since it was last asked
    this.shown = { found: false };
    this.sequence = 0;
    this.keyWanted = true;
    this.encoder = null;
    this.size = null;
    this.pending = new Map();  // timestamp -> the face-video's fields but its bytes
  }

  encode(video, region, time_ms) {
    const now = performance.now();
    this.budget = Math.min(kVideoBitrate / 8, this.budget + (now - this.budgetAt) * kVideoBitrate / 8000);
    this.budgetAt = now;
    if (this.budget <= 0) {
      ++this.skipped;
      return;
    }
    const W = video.videoWidth, H = video.videoHeight;
    if (region) {
      const choice = followFace(this.shown, region, W, H);
      this.shown = choice.region;
      if (choice.jumped) this.keyWanted = true;
    } else {
      this.shown = { found: false, x: 0, y: 0, width: W, height: H };
    }
    let size = [kFaceVideoSide, kFaceVideoSide];
    if (!this.shown.found) size = searchPictureSize(W, H);  // the whole frame
    if (!this.encoder || this.size[0] !== size[0] || this.size[1] !== size[1]) this.open(size);
    const rect = [this.shown.x, this.shown.y, this.shown.width, this.shown.height];
    const timestamp = time_ms * 1000;
    this.pending.set(timestamp, { type: 'face-video', time_ms, frame_width: W, frame_height: H, x: rect[0], y: rect[1], width: rect[2], height: rect[3] });
    const frame = new VideoFrame(draw(video, rect, size), { timestamp });
    this.encoder.encode(frame, { keyFrame: this.keyWanted });
    frame.close();
    this.keyWanted = false;
  }

  // Eight delta pictures half again as large as the rate allows: ask the encoder for less, in proportion.
  measure(bytes) {
    this.measured.pictures += 1;
    this.measured.bytes += bytes;
    if (this.measured.pictures < 8) return;
    const perPicture = this.measured.bytes / this.measured.pictures, allowed = kVideoBitrate / 8 / kFaceVideoFps;
    this.measured = { pictures: 0, bytes: 0 };
    if (perPicture <= 1.5 * allowed || this.asked <= kMinAskedBitrate) return;
    this.asked = Math.max(kMinAskedBitrate, Math.round(this.asked * allowed / perPicture));
    this.configure();
  }

  configure() {
    this.encoder.configure({ codec: 'vp8', width: this.size[0], height: this.size[1], bitrate: this.asked, framerate: kFaceVideoFps, latencyMode: 'realtime' });
    this.keyWanted = true;  // a configured encoder starts again
  }

  open(size) {
    if (this.encoder && this.encoder.state !== 'closed') this.encoder.close();
    this.size = size;
    this.pending.clear();
    this.keyWanted = true;
    this.encoder = new VideoEncoder({
      output: (chunk) => {
        const fields = this.pending.get(chunk.timestamp);
        this.pending.delete(chunk.timestamp);
        if (!fields) return;
        const vp8 = new Uint8Array(chunk.byteLength);
        chunk.copyTo(vp8);
        this.budget -= vp8.length;
        if (chunk.type !== 'key') this.measure(vp8.length);
        this.send({ ...fields, sequence: ++this.sequence, key: chunk.type === 'key', vp8 });
      },
      error: (e) => { this.failed = e.message; },
    });
    this.configure();
  }

  close() {
    if (this.encoder && this.encoder.state !== 'closed') this.encoder.close();
  }
}

export class CameraSender {
  // `send(message)` gets each face-video or face-crop; `now()` the call's clock in ms; `format`
  // 'vp8' or 'jpeg' (faceFormat()).
  constructor(video, send, now, format = 'jpeg', fps = kFaceVideoFps) {
    this.video = video;
    this.region = null;  // the server's latest face-region
    this.off = false;
    this.sent = 0;
    this.bytes = 0;
    this.busy = false;
    this.format = format;
    const out = (m) => {
      if (this.off) return;  // switched off while it was being encoded: a camera turned off sends nothing more
      send(m);
      ++this.sent;
      this.bytes += (m.vp8 ?? m.jpeg).length;
    };
    this.faceVideo = format === 'vp8' ? new FaceVideo(out) : null;
    this.timer = setInterval(async () => {
      if (this.off || this.busy || !video.videoWidth) return;
      if (this.faceVideo?.failed) {  // the encoder broke (a GPU process lost): JPEG from now on
        this.faceVideo.close();
        this.faceVideo = null;
        this.format = 'jpeg';
      }
      this.busy = true;
      try {
        if (this.faceVideo) this.faceVideo.encode(video, this.usableRegion(), now());
        else out(await this.crop(now()));
      } finally {
        this.busy = false;
      }
    }, 1000 / fps);
  }

  // The server asked for a key frame (it lost its place in the video).
  keyFrame() { if (this.faceVideo) this.faceVideo.keyWanted = true; }

  usableRegion() {
    const v = this.video, r = this.region;
    return r && r.found && r.x + r.width <= v.videoWidth && r.y + r.height <= v.videoHeight && r.width >= 8 && r.height >= 8 ? r : null;
  }

  async crop(time_ms) {
    const v = this.video, W = v.videoWidth, H = v.videoHeight, r = this.usableRegion();
    const rect = r ? [r.x, r.y, r.width, r.height] : [0, 0, W, H];
    const size = fit(rect[2], rect[3], r ? kFaceVideoSide : kFaceSearchWidth);
    return { type: 'face-crop', time_ms, frame_width: W, frame_height: H, x: rect[0], y: rect[1], width: rect[2], height: rect[3],
             jpeg: await jpeg(v, rect, size, 0.75) };
  }

  stop() {
    clearInterval(this.timer);
    this.faceVideo?.close();
  }
}
