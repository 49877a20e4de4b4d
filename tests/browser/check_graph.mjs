// Open archlog's HTML graph in Debian's Chromium, type a search, click an element, zoom, toggle
// the parameters, click the first finding of the list, take a screenshot, and print what a person
// would see as JSON.
// Usage: node check_graph.mjs PAGE.html SCREENSHOT.png SEARCH ELEMENT_ID
import { chromium } from "playwright-core";

const [page, screenshot, query, element] = process.argv.slice(2);
const browser = await chromium.launch({
  executablePath: "/usr/bin/chromium",
  args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
         "--disable-component-update", "--disable-sync"],
});
try {
  const tab = await browser.newPage({ viewport: { width: 1400, height: 800 } });
  await tab.goto("file://" + page);
  const elements = await tab.locator("g.node").count();
  await tab.locator("#search").fill(query);
  await tab.locator("#search").press("Enter");
  const matches = await tab.locator("g.node.match").count();
  const count = await tab.locator("#count").textContent();
  await tab.locator(`g.node[id="${element}"]`).click();
  const panel = await tab.locator("#panel").innerText();
  const before = await tab.locator("#view svg").getAttribute("viewBox");
  await tab.mouse.move(500, 400);
  await tab.mouse.wheel(0, -400);
  const after = await tab.locator("#view svg").getAttribute("viewBox");
  const legend = await tab.locator("#legend").innerText();
  const parametersHidden = await tab.locator('g.node[id^="p:"]').count();
  await tab.locator("#parameters").check();
  const parametersShown = await tab.locator('g.node[id^="p:"]').count();
  await tab.locator("#parameters").uncheck();
  const findings = await tab.locator("#findings li").allInnerTexts();
  const unfocused = await tab.locator("#view svg").getAttribute("viewBox");
  await tab.locator("#findings li").first().click();
  const focused = await tab.locator("g.node.match").evaluateAll(gs => gs.map(g => g.id).sort());
  const dimmed = await tab.locator("g.node.dim").count();
  const focusBox = await tab.locator("#view svg").getAttribute("viewBox");
  const findingPanel = await tab.locator("#panel").innerText();
  await tab.screenshot({ path: screenshot });
  console.log(JSON.stringify({ elements, matches, count, panel, zoomed: before !== after, legend, parametersHidden,
                               parametersShown, findings, focused, dimmed, refocused: focusBox !== unfocused,
                               findingPanel }));
} finally {
  await browser.close();
}
