"""The module graph's edges, shared by the local and the remote test: a module's node has one
drawn edge per requirement a running module provides, from that provider, and the tree names
what it requires (the declarations the runtime or the robot's debug server gave)."""
from selenium.webdriver.common.by import By
from view_harness import check, wait_js


def check_edges_of(d, module):
    """Opens the modules tab and checks `module`'s incoming edges; returns them as (rep, from)."""
    wait_js(d, f"strideView.tree?.modules?.some(m => m.name === '{module}' && Array.isArray(m.requires))", 20,
            f"{module} with its requirements in the tree")
    check(d.execute_script("return strideView.tree.graph") is True, "the tree says the graph is unknown")
    d.find_element(By.ID, "tab-modules").click()
    tree = d.execute_script("return strideView.tree")
    provider = {r["name"]: r["provider"] for r in tree["representations"]}
    running = {p for p in provider.values() if p}
    mod = next(m for m in tree["modules"] if m["name"] == module)
    check(module in running, f"{module} is not running")
    check(len(mod["requires"]) >= 3, f"{module} requires only {mod['requires']}")
    want = sorted((rep, provider[rep]) for rep in mod["requires"]
                  if provider.get(rep) in running and provider[rep] != module)
    check(len(want) >= 2, f"{module}'s requirements with a module providing them: {want}")
    drawn = sorted(tuple(e) for e in d.execute_script(
        "return [...document.querySelectorAll('#module-graph path.edge')]"
        ".filter(e => e.dataset.to === arguments[0]).map(e => [e.dataset.rep, e.dataset.from])", module))
    check(drawn == want, f"{module}'s edges drawn {drawn}, wanted {want}")
    for rep, prov in want:  # the providers' own declarations say they make it
        p = next(m for m in tree["modules"] if m["name"] == prov)
        check(rep in p["provides"], f"{prov} drawn as the provider of {rep} but provides {p['provides']}")
    total = d.execute_script("return document.querySelectorAll('#module-graph path.edge').length")
    check(total > len(want), f"only {total} edges in the whole graph")
    return want, total
