// A call member's camera in the browser (SPEC F8), as client/call/publisher.cpp sends it: the
// face region of the frame the server last reported (about 160 px), or the whole frame scaled
// to 320 px until it finds one, as JPEG, at most 15 a second; the neutral photo from the frame
// shown when it is taken. Pictures stay in memory.

const kCropSide = 160, kSearchWidth = 320, kPhotoSide = 480;

function fit(width, height, side) {
  const scale = Math.min(1, side / width, side / height);
  return [Math.max(1, Math.round(width * scale)), Math.max(1, Math.round(height * scale))];
}

async function jpeg(video, [sx, sy, sw, sh], [w, h], quality) {
  const canvas = new OffscreenCanvas(w, h);
  canvas.getContext('2d').drawImage(video, sx, sy, sw, sh, 0, 0, w, h);
  const blob = await canvas.convertToBlob({ type: 'image/jpeg', quality });
  return new Uint8Array(await blob.arrayBuffer());
}

// The neutral photo: the frame the preview shows now.
export function photoOf(video) {
  return jpeg(video, [0, 0, video.videoWidth, video.videoHeight], fit(video.videoWidth, video.videoHeight, kPhotoSide), 0.9);
}

export class CameraSender {
  // `send(message)` gets each face-crop; `now()` the call's clock in ms.
  constructor(video, send, now, fps = 15) {
    this.video = video;
    this.region = null;  // the server's latest face-region
    this.off = false;
    this.sent = 0;
    this.busy = false;
    this.timer = setInterval(async () => {
      if (this.off || this.busy || !video.videoWidth) return;
      this.busy = true;
      try {
        const crop = await this.crop(now());
        // Switched off while it was being encoded: a camera turned off sends nothing more.
        if (this.off) return;
        send(crop);
        ++this.sent;
      } finally {
        this.busy = false;
      }
    }, 1000 / fps);
  }

  async crop(time_ms) {
    const v = this.video, W = v.videoWidth, H = v.videoHeight, r = this.region;
    const found = r && r.found && r.x + r.width <= W && r.y + r.height <= H && r.width >= 8 && r.height >= 8;
    const rect = found ? [r.x, r.y, r.width, r.height] : [0, 0, W, H];
    const size = fit(rect[2], rect[3], found ? kCropSide : kSearchWidth);
    return { type: 'face-crop', time_ms, frame_width: W, frame_height: H, x: rect[0], y: rect[1], width: rect[2], height: rect[3],
             jpeg: await jpeg(v, rect, size, 0.75) };
  }

  stop() { clearInterval(this.timer); }
}
