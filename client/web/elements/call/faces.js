// <inkwire-call>'s faces (SPEC F10, F16): the session's style on every tile, the roster with each
// member's photo and landmarks handed to the renderer (call/tiles.js), each face shown when the
// sound of its moment plays, and the drawing loop. A mixin over SessionElement (one feature a file).

export const FacesMixin = (Base) => class extends Base {
  // The session's style on every tile, once the renderer is there.
  async showStyle(style) {
    this.styleSelect.value = style.renderer;
    await this.tilesReady;
    const reason = this.tiles.setStyle(style);
    if (reason) this.message.textContent = `the faces keep their look: ${reason}`;
  }


  // The roster on the tiles at once; each new photo (and its landmarks) handed to the renderer
  // as it arrives, the roster then given again so its tile shows the face.
  async updateRoster(session, roster) {
    this.roster = roster;
    this.showHostControls();
    const mine = roster.members.find((m) => m.member === roster.you);
    if (mine && !mine.face_found && mine.camera) this.message.textContent = 'no face found in your camera picture';
    await this.tilesReady;
    if (this.session !== session) return;
    this.tiles.setRoster(this.roster);
    for (const member of this.photos.keys()) if (!roster.members.some((m) => m.member === member)) this.photos.delete(member);
    for (const m of roster.members) {
      const photo = m.assets[0]?.hash.join();
      if (m.assets.length !== 2 || this.photos.get(m.member) === photo) continue;
      this.photos.set(m.member, photo);
      try {
        const [bytes, landmarks] = await Promise.all([session.fetchAsset(m.assets[0]), session.fetchAsset(m.assets[1])]);
        if (this.session !== session || this.photos.get(m.member) !== photo) continue;
        this.tiles.setMemberFace(m.member, bytes, new TextDecoder().decode(landmarks));
        this.tiles.setRoster(this.roster);
        const face = this.expressions.get(m.member);
        if (face) this.tiles.setFace(m.member, face);
      } catch (error) {
        this.message.textContent = `cannot show ${m.name}: ${error.message}`;
      }
    }
  }

  // A face (member-layers, or member-face from a server of version 7 or 8) comes when the sound of its
  // moment plays, so the mouth moves with the voice.
  faceArrived(m) {
    const due = this.link?.localTime(m.member, m.time_ms);
    const show = () => {
      if (!this.session) return;
      this.expressions.set(m.member, m);
      if (this.tiles.view) this.tiles.setFace(m.member, m);
    };
    if (due && due > performance.now()) setTimeout(show, due - performance.now());
    else show();
  }

  loop() {
    if (!this.hasAttribute('joined')) return;
    if (this.tiles.view && this.tiles.due()) {
      try {
        if (this.tiles.draw(performance.now() / 1000, this.isHost ? this.captionDecorator : null)) this.firstFaceAt ??= performance.now();
      } catch (error) {
        this.fail(`the call cannot be drawn: ${error.message}`);
        return;
      }
    }
    requestAnimationFrame(() => this.loop());
  }
};
