// The knitting page's style, inlined into every page (page_writer.cpp): a two-column layout
// (the 3D view and chart beside the instructions), one column on narrow screens, a dark scheme,
// larger type on request (body.big), and print without the controls.
#include "hand_web/page_writer.hpp"

namespace skein::hand_web {

const char* const kPageStyle = R"CSS(
:root { --done: #43a047; --current: #e53935; --todo: #c7c7c7; --ink: #1b1b1b; --paper: #fafaf7;
  --line: #d0d0c8; --accent: #1565c0; font-family: system-ui, sans-serif; }
@media (prefers-color-scheme: dark) { :root { --ink: #eee; --paper: #161616; --line: #444; } }
* { box-sizing: border-box; }
html, body { margin: 0; height: 100%; background: var(--paper); color: var(--ink); }
body { display: grid; grid-template-columns: minmax(0, 3fr) minmax(320px, 2fr);
  grid-template-rows: auto minmax(0, 1fr); height: 100vh; overflow: hidden; }
header { grid-column: 1 / -1; display: flex; flex-wrap: wrap; gap: .4em; align-items: center;
  padding: .4em .6em; border-bottom: 1px solid var(--line); }
header h1 { font-size: 1.1em; margin: 0 .6em 0 0; white-space: nowrap; overflow: hidden;
  text-overflow: ellipsis; max-width: 40vw; }
#counter { font-variant-numeric: tabular-nums; font-weight: 600; margin-right: auto; }
button { font: inherit; padding: .35em .7em; border: 1px solid var(--line); border-radius: .4em;
  background: transparent; color: inherit; cursor: pointer; min-height: 2.4em; }
button:focus-visible { outline: 3px solid var(--accent); }
#view { position: relative; min-height: 0; min-width: 0; }
#view canvas { display: block; width: 100%; height: 100%; touch-action: none; }
#no3d { padding: 1em; }
#panel { display: flex; flex-direction: column; gap: .6em; padding: .8em; overflow: auto;
  border-left: 1px solid var(--line); min-width: 0; }
#heading { font-size: .9em; opacity: .75; }
#where { font-size: 1.3em; font-weight: 700; }
#instr { font-size: 1.35em; line-height: 1.5; margin: 0; overflow-wrap: anywhere; }
#instr mark { background: var(--current); color: #fff; border-radius: .2em; padding: 0 .15em; }
#instr mark.line { background: transparent; color: inherit; box-shadow: inset 0 -.25em 0 var(--current); }
#said { font-size: .95em; opacity: .8; }
#chart { margin: 0; }
#chart figcaption { font-size: .85em; opacity: .8; }
#chartScroll { overflow: auto; max-height: 40vh; }
#chartScroll svg { display: block; width: min(100%, calc(var(--cols) * 18px + 60px)); height: auto; }
body.big #chartScroll svg { width: max(100%, calc(var(--cols) * 27px + 90px)); }
#chartScroll .sq { fill: #fff; stroke: #888; stroke-width: .6; }
#chartScroll .dot { fill: #222; }
#chartScroll text { font-size: 8px; fill: var(--ink); }
#chartRow { fill: rgba(21, 101, 192, .22); stroke: var(--accent); stroke-width: 1; }
#chartSt { fill: none; stroke: var(--current); stroke-width: 2.2; }
#counts { font-variant-numeric: tabular-nums; }
#next { font-size: 1.6em; min-height: 3.2em; width: 100%; background: var(--accent); color: #fff;
  border: none; margin-top: auto; }
#steps { display: grid; grid-template-columns: repeat(3, 1fr); gap: .4em; }
#legend span { display: inline-block; width: .9em; height: .9em; border-radius: .2em;
  vertical-align: -.1em; margin: 0 .25em 0 .6em; }
#toast { position: absolute; left: .6em; bottom: .6em; background: rgba(0,0,0,.7); color: #fff;
  padding: .2em .6em; border-radius: .3em; opacity: 0; transition: opacity .3s; }
#toast.on { opacity: 1; }
#selftest:empty, #perf:empty, #note:empty { display: none; }
#note { font-size: .9em; border-left: 4px solid #f9a825; padding-left: .5em; }
details { font-size: .9em; }
details pre { white-space: pre-wrap; font-size: .85em; max-height: 40vh; overflow: auto; }
body.big { font-size: 150%; }
body.big #instr { font-size: 1.8em; }
@media (max-width: 760px) {
  body { grid-template-columns: minmax(0, 1fr); grid-template-rows: auto 36vh minmax(0, 1fr);
    height: auto; min-height: 100vh; overflow: auto; }
  #panel { border-left: none; border-top: 1px solid var(--line); }
  header { font-size: .9em; flex-wrap: nowrap; }
  #counter { min-width: 0; overflow: hidden; text-overflow: ellipsis; white-space: nowrap; }
  body.big header h1 { display: none; }
  header h1 { max-width: 30vw; }
  #view { height: 36vh; }
}
@media print { #view, header button, #next, #steps { display: none; } body { display: block; } }
)CSS";

}  // namespace skein::hand_web
