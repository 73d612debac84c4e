// <inkwire-call>'s publishing (SPEC F9): what goes out, said to the call (camera, microphone) and
// done; mute and camera off. A mixin over SessionElement (one feature a file).

export const PublishingMixin = (Base) => class extends Base {
  // What goes out, said to the call and done: voice flows only while it says a microphone is on.
  publish() {
    const microphone = !!this.hasVoice && !this.muted;
    if (this.link) this.link.sending = microphone && !!this.session;
    this.session?.send({ type: 'publish', camera: !!this.camera && !this.cameraOff, microphone });
    this.muteButton.textContent = this.muted ? 'Unmute' : 'Mute';
    this.cameraButton.textContent = this.cameraOff ? 'Camera on' : 'Camera off';
    this.muteButton.disabled = !this.hasVoice;
    this.cameraButton.disabled = !this.camera;
  }

  setMuted(muted) {
    this.muted = muted;
    this.publish();
  }

  setCameraOff(off) {
    this.cameraOff = off;
    if (this.camera) this.camera.off = off;
    this.publish();
  }
};
