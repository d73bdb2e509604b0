// The view's token proof (PROTOCOL.md, "Who may connect"): HMAC-SHA256 over the two nonces.
// @noble/hashes (npm, served under /vendor/noble-hashes/): crypto.subtle is missing on plain-http
// non-loopback pages, so the page cannot use the browser's own.
import { hmac } from "/vendor/noble-hashes/hmac.js";
import { sha256 } from "/vendor/noble-hashes/sha2.js";

export const hmacSha256 = (key, message) => hmac(sha256, key, message);

export const hex = (bytes) => Array.from(bytes, (b) => b.toString(16).padStart(2, "0")).join("");
const utf8 = (s) => new TextEncoder().encode(s);

// The page's answer to {"type":"auth","nonce":...}, and the proof the bridge must send back.
export function authAnswer(token, serverNonce) {
  const nonce = new Uint8Array(32);
  crypto.getRandomValues(nonce);
  const clientNonce = hex(nonce);
  const key = utf8(token);
  const proof = hex(hmacSha256(key, utf8(`stride-view-1 client${serverNonce}${clientNonce}`)));
  const expect = hex(hmacSha256(key, utf8(`stride-view-1 server${serverNonce}${clientNonce}`)));
  return { message: { op: "auth", nonce: clientNonce, proof }, expect };
}

// The token from the page's URL fragment (#token=T), never sent to the server by the browser.
export function tokenFromFragment(hash) {
  const m = /(?:^#|&)token=([^&]*)/.exec(hash || "");
  return m ? decodeURIComponent(m[1]) : null;
}
