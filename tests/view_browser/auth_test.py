#!/usr/bin/env python3
"""The page's own HMAC-SHA256 proves a token to the real bridge (`--token-file` on loopback):
opened with #token=T it connects and works; with a wrong token the bridge closes it and the
page says so, with no hello; a read-only token connects and is marked read only."""
import os
import sys
import tempfile

from view_harness import ViewProcess, check, console, main, open_page, wait_js

TOKEN = "view-browser-test-token-0123456789"
READ_ONLY = "view-browser-read-only-token-98765"


def test(stride, d):
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "tokens")
        with open(path, "w") as f:
            f.write(f"{TOKEN}\nread-only {READ_ONLY}\n")
        os.chmod(path, 0o600)
        with ViewProcess(stride, ["scenes/nao_stand.xml", "--token-file", path]) as view:
            d.get(view.url + "#token=wrong-token-but-long-enough")
            wait_js(d, "window.strideView && strideView.conn.state.startsWith('refused')", 20,
                    "the page says the bridge refused the token")
            check(d.execute_script("return strideView.hello") is None, "hello reached a page with a wrong token")
            d.get("about:blank")
            d.get(view.url)  # no token at all
            wait_js(d, "window.strideView && strideView.conn.state.startsWith('needs token')", 20,
                    "the page asks for a token")
            check(d.execute_script("return strideView.hello") is None, "hello reached a page without a token")
            d.get("about:blank")
            open_page(d, view.url + f"#token={TOKEN}")
            state, text = console(d, "echo proved")
            check(state == "ok" and text.strip() == "proved", f"echo after the proof: {state} {text!r}")
            check(d.execute_script("return strideView.conn.state") == "connected", "state after the proof")
            d.get("about:blank")
            open_page(d, view.url + f"#token={READ_ONLY}")
            check(d.execute_script("return strideView.conn.readOnly") is True, "the read-only token's mark")
            state, text = console(d, "run")
            check(state == "error", f"a read-only page ran the simulation: {state} {text!r}")
            print(f"wrong token refused, no token asked for, token proved, read-only refused 'run': {text}")


if __name__ == "__main__":
    sys.exit(main(test))
