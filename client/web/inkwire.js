// The web client's one script: `<script type="module" src="https://SERVER/inkwire.js">` defines
// <inkwire-turntable> (a product a customer turns), <inkwire-conference> (a speaker's face
// rebuilt from expression codes), <inkwire-call> (a call every member joins with their own
// camera and microphone) and <inkwire-scene> (a shared scene in any NPR style, drawn by the
// renderers compiled to WebAssembly). Each is described in docs/products.md, calls.md or scenes.md.
export { InkwireTurntable } from './elements/turntable.js';
export { InkwireConference } from './elements/conference.js';
export { InkwireCall } from './elements/call.js';
export { InkwireScene } from './elements/scene.js';
