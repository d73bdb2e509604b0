// Debug requests: each with on/off/quiet, sent as `dr <name> <state>`.

export class DebugList {
  constructor(container, consolePane) {
    this.container = container;
    this.consolePane = consolePane;
  }

  setTree(msg) {
    this.container.textContent = "";
    for (const d of msg.debug || []) {
      const row = document.createElement("div");
      row.className = "dr-row";
      const name = document.createElement("span");
      name.textContent = d.name;
      const sel = document.createElement("select");
      sel.className = "dr-select";
      sel.dataset.dr = d.name;
      for (const s of ["off", "on", "quiet"]) sel.add(new Option(s, s, false, s === d.state));
      sel.onchange = async () => {
        const reply = await this.consolePane.run(`dr ${d.name} ${sel.value}`);
        if (!reply.ok) sel.value = d.state;
        else d.state = sel.value;
      };
      row.append(name, sel);
      this.container.appendChild(row);
    }
  }
}
