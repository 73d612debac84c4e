// <inkwire-call>'s membership (SPEC F8, F19): joining under a name, entering (the neutral photo
// and the camera's face video sent, the grid shown), a lost connection joined again under the same
// name, and leaving. A mixin over SessionElement (one feature a file).
import { CameraSender, faceFormat } from '../../call/camera.js';

export const MembershipMixin = (Base) => class extends Base {
  join() {
    if (this.session) return;
    this.shutOut = '';
    const name = this.nameInput.value.trim() || this.getAttribute('name') || 'guest';
    const token = this.joinTokenForRoom(), withHostKey = !!this.hostKey && token === this.hostKey;
    const session = (this.session = this.link.open(this.serverUrl(), this.getAttribute('session') ?? '', token, name.slice(0, 64),
                                                   this.hasAttribute('open-room')));
    session.addEventListener('error', (e) => {
      // A key kept for a room of this name that is gone (a new one took its name): forgotten, and joined without it.
      if (withHostKey && !this.hasAttribute('joined') && this.session === session) {
        this.forgetHostKey();
        this.leave();
        this.join();
        return;
      }
      this.fail(e.detail);
    });
    session.addEventListener('host-key', (e) => this.keepHostKey(e.detail));
    // Locked out or removed by the host: said, and not joined again by itself.
    session.addEventListener('shut-out', (e) => {
      this.rejoinUntil = 0;
      this.shutOut = e.detail;
    });
    session.addEventListener('refused', (e) => this.refused(e.detail));
    session.addEventListener('snapshot', (e) => this.entered(session, e.detail), { once: true });
    session.addEventListener('state', (e) => { if (e.detail.type === 'style-change') this.showStyle(e.detail); });
    session.addEventListener('roster', (e) => this.updateRoster(session, e.detail));
    session.addEventListener('face-region', (e) => { if (this.camera) this.camera.region = e.detail; });
    session.addEventListener('key-frame-request', () => this.camera?.keyFrame());
    session.addEventListener('member-layers', (e) => this.faceArrived(e.detail));
    session.addEventListener('member-face', (e) => this.faceArrived(e.detail));
    session.addEventListener('close', () => this.lost(session));
  }

  // A connection lost while in the call (Wi-Fi, a laptop lid, a server gone quiet: SPEC F19) is
  // joined again under the same name, every 2 s for a minute; the server gives the member its
  // tile back. Leaving on purpose (hangUp) stops that.
  lost(session) {
    if (this.session !== session) return;
    if (this.hasAttribute('joined') && !this.shutOut) this.rejoinUntil = performance.now() + 60000;
    this.leave();
    if (!(performance.now() < this.rejoinUntil) || !this.isConnected) return;
    this.message.textContent = 'the connection was lost: joining again';
    setTimeout(() => { if (!this.session && this.isConnected && performance.now() < this.rejoinUntil) this.join(); }, 2000);
  }

  // The Leave button: out of the call, and no joining again.
  hangUp() {
    this.rejoinUntil = 0;
    this.leave();
  }

  async entered(session, snapshot) {
    if (this.rejoinUntil) this.message.textContent = '';
    this.rejoinUntil = 0;
    this.reason = this.voiceReason ?? this.reason;
    if (this.preview.videoWidth && !this.photo) await this.takePhoto();
    const format = await faceFormat();
    if (this.session !== session) return;
    if (this.photo) session.send({ type: 'neutral-photo', jpeg: this.photo });
    if (this.preview.videoWidth) this.camera = new CameraSender(this.preview, (m) => this.session?.send(m), () => this.now(), format);
    if (this.camera) this.camera.off = this.cameraOff;
    this.publish();
    this.prejoin.hidden = true;
    this.grid.hidden = this.controls.hidden = false;
    this.joinedAt ??= performance.now();
    this.setAttribute('joined', '');
    this.dispatchEvent(new Event('joined'));
    this.showStyle(snapshot.style);
    this.loop();
  }

  // Out of the call: the session closed, nothing sent, the pre-join shown again.
  leave() {
    this.session?.close();  // says leave first, in the worker
    this.session = null;
    if (this.link) this.link.sending = false;
    this.camera?.stop();
    this.camera = null;
    this.photos.clear();
    this.expressions.clear();
    this.roster = { you: 0, members: [] };
    if (this.tiles.view) this.tiles.setRoster(this.roster);
    if (this.hasAttribute('joined')) this.removeAttribute('joined');
    this.prejoin.hidden = false;
    this.grid.hidden = this.controls.hidden = true;
  }
};
