// The console pane: an input line with history (up/down) sending `cmd` lines, and their output.
// Every command the page sends on the user's behalf goes through run(), so it shows here too.

const MAX_LINES = 2000;

export class ConsolePane {
  constructor(conn, input, output) {
    this.conn = conn;
    this.input = input;
    this.output = output;
    this.history = [];
    this.cursor = 0;
    this.count = 0; // commands sent: #con-<n> is the n-th, its reply line has data-for="con-<n>"
    input.addEventListener("keydown", (ev) => this.onKey(ev));
  }

  onKey(ev) {
    if (ev.key === "Enter") {
      const line = this.input.value.trim();
      this.input.value = "";
      if (!line) return;
      if (this.history[this.history.length - 1] !== line) this.history.push(line);
      this.cursor = this.history.length;
      this.run(line);
    } else if (ev.key === "ArrowUp") {
      if (this.cursor > 0) this.input.value = this.history[--this.cursor];
      ev.preventDefault();
    } else if (ev.key === "ArrowDown") {
      this.cursor = Math.min(this.cursor + 1, this.history.length);
      this.input.value = this.history[this.cursor] || "";
      ev.preventDefault();
    }
  }

  // Appends a line, or puts it after `after` (a command's output follows its command line).
  print(text, cls, after = null) {
    const el = document.createElement("div");
    el.className = cls;
    el.textContent = text;
    if (after && after.isConnected) after.after(el);
    else this.output.appendChild(el);
    while (this.output.childElementCount > MAX_LINES) this.output.firstElementChild.remove();
    this.output.scrollTop = this.output.scrollHeight;
    return el;
  }

  // Sends one console line; prints it, then its output or its error. Resolves with the reply.
  async run(line) {
    const cmd = this.print(`> ${line}`, "con-cmd");
    cmd.id = `con-${++this.count}`;
    const reply = await this.conn.cmd(line);
    let at = cmd;
    const out = (reply.output || "").replace(/\n$/, "");
    if (out) at = this.print(out, "con-out", at);
    if (!reply.ok) at = this.print(reply.error || "failed", "con-err", at);
    for (let el = cmd.nextElementSibling; el && el !== at.nextElementSibling; el = el.nextElementSibling)
      el.dataset.for = cmd.id;
    cmd.dataset.done = reply.ok ? "ok" : "error";
    return reply;
  }
}
