// The web client's one script: `<script type="module" src="https://SERVER/inkwire.js">` defines
// <inkwire-turntable> (a product a customer turns) and <inkwire-conference> (a speaker's face
// rebuilt from expression codes). See README "On a web page".
export { InkwireTurntable } from './elements/turntable.js';
export { InkwireConference } from './elements/conference.js';
