// Debian's Firefox ESR driven for the Python browser tests (tests/web/browser_support.py): puppeteer-core
// over WebDriver BiDi, no geckodriver and nothing downloaded. One JSON request per line on stdin,
// one JSON answer per line on stdout:
//   {"get": URL}  {"script": BODY}  (BODY as selenium's execute_script: may `return`, may await)
//   {"screenshot": PATH}  {"quit": true}
// Answers {"ok": VALUE} or {"error": MESSAGE}.
//   node firefox_bridge.mjs PROFILE_DIR WIDTH HEIGHT [PREF=VALUE ...]
import { createInterface } from 'node:readline';

import puppeteer from 'puppeteer-core';

const [profile, width, height, ...prefArgs] = process.argv.slice(2);
const prefs = {
  // A fake camera and a tone for a microphone, without asking.
  'media.navigator.streams.fake': true,
  'media.navigator.permission.disabled': true,
  // Sound plays without a click, as a person's click would allow.
  'media.autoplay.default': 0,
  'media.autoplay.block-webaudio': false,
  'browser.shell.checkDefaultBrowser': false,
  'datareporting.policy.dataSubmissionEnabled': false,
  'toolkit.telemetry.reportingpolicy.firstRun': false,
};
for (const p of prefArgs) {
  const [key, value] = p.split(/=(.*)/s);
  prefs[key] = value === 'true' ? true : value === 'false' ? false : /^-?\d+$/.test(value) ? Number(value) : value;
}
const browser = await puppeteer.launch({
  browser: 'firefox', executablePath: '/usr/bin/firefox-esr', headless: false, userDataDir: profile,
  defaultViewport: { width: Number(width), height: Number(height) }, extraPrefsFirefox: prefs,
  args: [`--width=${width}`, `--height=${height}`],
});
const page = (await browser.pages())[0] ?? (await browser.newPage());
page.on('console', (m) => process.stderr.write(`console: ${m.text()}\n`));
page.on('pageerror', (e) => process.stderr.write(`page error: ${e.message}\n`));

// As selenium's script timeout (30 s): a page that stops answering fails its test in 30 s, where
// puppeteer would wait 180 s for each evaluation.
const SCRIPT_TIMEOUT_MS = 30000;
const withinScriptTimeout = (promise) => Promise.race([promise, new Promise((resolve, reject) => {
  setTimeout(() => reject(new Error(`script timed out after ${SCRIPT_TIMEOUT_MS / 1000} s`)), SCRIPT_TIMEOUT_MS).unref();
})]);
const answer = (value) => process.stdout.write(`${JSON.stringify(value)}\n`);
for await (const line of createInterface({ input: process.stdin })) {
  let request;
  try {
    request = JSON.parse(line);
    if (request.get) {
      await page.goto(request.get, { waitUntil: 'load' });
      answer({ ok: null });
    } else if (request.script !== undefined) {
      // eslint-disable-next-line no-new-func
      const value = await withinScriptTimeout(page.evaluate(`(async () => { ${request.script} })()`));
      answer({ ok: value === undefined ? null : value });
    } else if (request.screenshot) {
      await page.screenshot({ path: request.screenshot });
      answer({ ok: null });
    } else if (request.quit) {
      answer({ ok: null });
      break;
    }
  } catch (error) {
    answer({ error: String(error?.message ?? error) });
  }
}
await browser.close();
