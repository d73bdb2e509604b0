// Values watched as text: numbers from the sample stream, anything else polled with `get`.

const POLL_MS = 500;

export class Watches {
  constructor(container, store, conn) {
    this.container = container;
    this.store = store;
    this.conn = conn;
    this.items = new Map(); // key -> {el, valueEl, number, busy}
    setInterval(() => this.poll(), POLL_MS);
  }

  add(key, number) {
    if (this.items.has(key)) return;
    if (number && !this.store.add(key, "watch")) return;
    const el = document.createElement("div");
    el.className = "watch";
    el.dataset.key = key;
    el.innerHTML = `<span class="watch-key"></span><span class="watch-value">.</span><button>x</button>`;
    el.querySelector(".watch-key").textContent = key;
    el.querySelector("button").onclick = () => this.remove(key);
    this.container.appendChild(el);
    this.items.set(key, { el, valueEl: el.querySelector(".watch-value"), number, busy: false });
  }

  remove(key) {
    const item = this.items.get(key);
    if (!item) return;
    if (item.number) this.store.remove(key, "watch");
    item.el.remove();
    this.items.delete(key);
  }

  // Numbers: the latest sample. Others: one `get` at a time per key.
  refresh() {
    for (const [key, item] of this.items) {
      if (!item.number) continue;
      const v = this.store.latest(key);
      if (v !== null) item.valueEl.textContent = String(v);
    }
  }

  poll() {
    for (const [key, item] of this.items) {
      if (item.number || item.busy) continue;
      item.busy = true;
      this.conn.get(key).then((v) => {
        item.busy = false;
        item.valueEl.textContent = v.error ? v.error : (v.text || "").replace(/\n$/, "");
      });
    }
  }
}
