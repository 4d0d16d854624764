// The page's style sheet, injected once (the page is one file: no separate CSS).
const css = `
html, body { margin: 0; height: 100%; font: 13px/1.35 system-ui, sans-serif; color: #222; background: #fff; }
#app { display: flex; height: 100%; }
#view { flex: 1 1 auto; position: relative; min-width: 200px; }
#view canvas { display: block; width: 100%; height: 100%; }
#side { flex: 0 0 360px; overflow-y: auto; border-left: 1px solid #ccc; padding: 8px 10px; background: #fafafa; }
#side h2 { font-size: 14px; margin: 10px 0 4px; }
#side h3 { font-size: 13px; margin: 8px 0 2px; color: #444; }
#toolbar { position: absolute; top: 8px; left: 8px; display: flex; gap: 6px; flex-wrap: wrap; }
#toolbar button, #toolbar select, #toolbar label { font: inherit; background: rgba(255,255,255,.88); border: 1px solid #aaa;
  border-radius: 4px; padding: 3px 8px; }
#title { position: absolute; bottom: 6px; left: 8px; color: #555; pointer-events: none; }
#info { white-space: pre; font: 12px/1.4 ui-monospace, monospace; background: #fff; border: 1px solid #ddd; padding: 6px;
  min-height: 3em; overflow-x: auto; }
.toggle { display: block; margin: 1px 0; white-space: nowrap; overflow: hidden; text-overflow: ellipsis; }
.swatch { display: inline-block; width: 10px; height: 10px; margin: 0 4px; border-radius: 2px; vertical-align: middle; }
.label3d { position: absolute; font: 11px system-ui, sans-serif; color: #000; background: rgba(255,255,200,.85);
  border: 1px solid #997; border-radius: 3px; padding: 0 3px; pointer-events: none; transform: translate(6px, -50%); white-space: nowrap; }
canvas.plot { width: 100%; border: 1px solid #ddd; background: #fff; display: block; margin: 2px 0 6px; }
.legend { font-size: 12px; color: #555; }
.row { margin: 4px 0; }
`;

export function injectStyle() {
  const s = document.createElement('style');
  s.textContent = css;
  document.head.appendChild(s);
}
