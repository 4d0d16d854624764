// ESLint for the viewer's JavaScript (issue 25, "habits"): the recommended rules, browser globals
// for the page's modules and Node's for the build script; run by ctest `viewer_lint`
// (tests/browser/CMakeLists.txt) and by `npm run lint`.
import js from "@eslint/js";
import globals from "globals";

export default [
  js.configs.recommended,
  {
    files: ["src/**/*.js"],
    languageOptions: { ecmaVersion: 2022, sourceType: "module", globals: { ...globals.browser } },
    rules: { "no-unused-vars": ["error", { args: "none" }] },
  },
  {
    files: ["build.mjs"],
    languageOptions: { ecmaVersion: 2022, sourceType: "module", globals: { ...globals.node } },
  },
];
