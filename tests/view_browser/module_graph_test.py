#!/usr/bin/env python3
"""The module graph: every module the tree names is drawn, PatternWalk with an edge from the
provider of each thing it requires; choosing another provider in the
providers table runs `mr`, which `get provider:<Rep>` in the console pane and the next tree
message both read back; `mr <Rep> default` returns to the configured one."""
import sys

from graph_edges import check_edges_of
from selenium.webdriver.common.by import By
from view_harness import ViewProcess, check, choose, console, main, open_page, value_of, wait_js

REP = "PostureCorrectedRequest"
SEL = f'select.provider-select[data-rep="{REP}"]'


def provider_in_tree(d):
    return d.execute_script(
        f"const r = strideView.tree.representations.find(r => r.name === '{REP}'); return r && r.provider;")


def test(stride, d):
    with ViewProcess(stride, ["scenes/walking/open_loop_medium.xml"]) as view:
        open_page(d, view.url)
        console(d, "step 1")  # the blackboard holds every representation after one frame
        d.find_element(By.ID, "tree-refresh").click()
        wait_js(d, f"strideView.tree && strideView.tree.representations.some(r => r.name === '{REP}')", 20,
                f"{REP} in the tree")
        d.find_element(By.ID, "tab-modules").click()
        names = d.execute_script("return strideView.tree.modules.map(m => m.name)")
        drawn = d.execute_script("return [...document.querySelectorAll('#module-graph g.module')]"
                                 ".map(g => g.dataset.module)")
        check(sorted(names) == sorted(drawn), f"modules {sorted(names)} but drawn {sorted(drawn)}")
        edges, total = check_edges_of(d, "PatternWalk")
        # Module times come only while the graph shows (the tab asked for them): a step shows them.
        console(d, "step 12")
        ms_js = ("const e = document.querySelector('#module-graph g.module[data-module=\"PatternWalk\"] .module-ms');"
                 " return e ? e.textContent : null")
        wait_js(d, f"(() => {{ {ms_js} }})() && /[1-9].* (ms|\u00b5s)$/.test((() => {{ {ms_js} }})())", 15,
                "PatternWalk's time (non-zero)")
        ms_text = d.execute_script(ms_js)
        before = provider_in_tree(d)
        values = d.execute_script("return [...document.querySelector(arguments[0]).options].map(o => o.value)", SEL)
        check(before in values and "HipStrategy" in values, f"providers offered: {values}")
        swap_to = "HipStrategy" if before != "HipStrategy" else "AnkleStrategy"
        n = d.execute_script("return strideView.consolePane.count")
        choose(d, SEL, swap_to)
        wait_js(d, f"document.getElementById('con-{n + 1}') && document.getElementById('con-{n + 1}').dataset.done", 15,
                "the mr command's reply")
        line = d.execute_script(f"return document.getElementById('con-{n + 1}').textContent")
        check(line == f"> mr {REP} {swap_to}", f"the select sent {line!r}")
        state, text = console(d, f"get provider:{REP}")
        check(state == "ok" and text.strip() == swap_to, f"get provider:{REP} -> {text!r} (wanted {swap_to})")
        wait_js(d, f"strideView.tree.representations.find(r => r.name === '{REP}').provider === '{swap_to}'", 15,
                "the refreshed tree names the new provider")
        check(value_of(d, SEL) == swap_to, "the select shows the swap")
        check(d.execute_script(f"return !!document.querySelector('#module-graph g.module[data-module=\"{swap_to}\"]:not(.inactive)')"),
              f"{swap_to} is not drawn active in the graph")
        choose(d, SEL, "default")
        wait_js(d, f"strideView.tree.representations.find(r => r.name === '{REP}').provider === '{before}'", 15,
                f"mr default returns to {before}")
        print(f"{len(names)} modules drawn, {total} edges, PatternWalk's: {edges} ({ms_text}); {REP}: {before} -> {swap_to} -> default ({before})")


if __name__ == "__main__":
    sys.exit(main(test))
