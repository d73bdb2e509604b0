// A plot's shown data as CSV, its picture as PNG, and a download of either.

// Rows of data ([x, ys...]) with x in [xmin, xmax], as CSV with a header of the keys.
export function toCsv(keys, data, xmin, xmax) {
  const lines = [["t", ...keys].join(",")];
  const xs = data[0];
  for (let i = 0; i < xs.length; i++) {
    if (xs[i] < xmin || xs[i] > xmax) continue;
    const row = [xs[i]];
    for (let c = 1; c < data.length; c++) row.push(data[c][i] === null ? "" : data[c][i]);
    lines.push(row.join(","));
  }
  return lines.join("\n") + "\n";
}

// The uPlot's canvas on white with the curves' names above it, as a PNG data URL.
export function toPng(u, keys, colours) {
  const src = u.ctx.canvas;
  const legend = 18 * keys.length + 6;
  const out = document.createElement("canvas");
  out.width = src.width;
  out.height = src.height + legend;
  const ctx = out.getContext("2d");
  ctx.fillStyle = "#fff";
  ctx.fillRect(0, 0, out.width, out.height);
  ctx.font = "14px sans-serif";
  keys.forEach((k, i) => {
    ctx.fillStyle = colours[i];
    ctx.fillRect(8, 6 + 18 * i, 14, 10);
    ctx.fillStyle = "#222";
    ctx.fillText(k, 28, 16 + 18 * i);
  });
  ctx.drawImage(src, 0, legend);
  return out.toDataURL("image/png");
}

export function download(name, href) {
  const a = document.createElement("a");
  a.href = href;
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
}

export function csvHref(text) {
  return URL.createObjectURL(new Blob([text], { type: "text/csv" }));
}
