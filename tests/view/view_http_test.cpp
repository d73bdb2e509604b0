// `stride view` over HTTP: the page and the vendor files with their types, 404 for what is not
// there or outside the roots, 405 for other methods.
#include <gtest/gtest.h>

#include "tests/view/view_client.hpp"

namespace stride::view_test {
namespace {

class ViewHttp : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    view_ = new ViewProcess({scene_path("nao_stand_controlled.xml")}, "127.0.0.1", "http");
  }
  static void TearDownTestSuite() {
    delete view_;
    view_ = nullptr;
  }
  static ViewProcess* view_;
};
ViewProcess* ViewHttp::view_ = nullptr;

TEST_F(ViewHttp, ServesThePageAndVendorFiles) {
  ASSERT_NE(view_->port(), 0) << view_->out() << view_->err();
  const std::string page_dir = std::string(STRIDE_SOURCE_DIR) + "/console/view/web";
  if (std::filesystem::exists(page_dir + "/index.html")) {
    const HttpReply index = http_get(view_->port(), "/");
    EXPECT_EQ(index.status, 200);
    EXPECT_EQ(index.content_type, "text/html; charset=utf-8");
    EXPECT_EQ(index.body, test_support::read_text(page_dir + "/index.html"));
  }
  const HttpReply three = http_get(view_->port(), "/vendor/three/build/three.min.js");
  EXPECT_EQ(three.status, 200);
  EXPECT_EQ(three.content_type, "text/javascript; charset=utf-8");
  EXPECT_EQ(three.body, test_support::read_text("/usr/share/javascript/three/three.min.js"));
  const HttpReply uplot = http_get(view_->port(), "/vendor/uplot/uPlot.min.css?v=1");
  EXPECT_EQ(uplot.status, 200);
  EXPECT_EQ(uplot.content_type, "text/css; charset=utf-8");
  EXPECT_EQ(uplot.body,
            test_support::read_text(std::string(STRIDE_SOURCE_DIR) +
                                    "/.deps/web/node_modules/uplot/dist/uPlot.min.css"));
  const HttpReply hmac = http_get(view_->port(), "/vendor/noble-hashes/hmac.js");
  EXPECT_EQ(hmac.status, 200);
  EXPECT_EQ(hmac.content_type, "text/javascript; charset=utf-8");
  EXPECT_EQ(hmac.body,
            test_support::read_text(std::string(STRIDE_SOURCE_DIR) +
                                    "/.deps/web/node_modules/@noble/hashes/esm/hmac.js"));
}

TEST_F(ViewHttp, RefusesTraversalAndUnknownPaths) {
  ASSERT_NE(view_->port(), 0);
  for (const char* target :
       {"/../../../etc/passwd", "/vendor/three/../../../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd",
        "/vendor/uplot/..%2f..%2fpackage.json", "/vendor/", "/vendor/other/x.js", "/nothing.html",
        "/vendor/three/build", "//etc/passwd", "/vendor/three//build/three.min.js"}) {
    const HttpReply r = http_get(view_->port(), target);
    EXPECT_EQ(r.status, 404) << target;
    EXPECT_EQ(r.body.find("root:"), std::string::npos) << target;
  }
  EXPECT_EQ(http_get(view_->port(), "/vendor/three/build/three.min.js", http::verb::post).status,
            405);
  const HttpReply head = http_get(view_->port(), "/vendor/uplot/uPlot.min.css", http::verb::head);
  EXPECT_EQ(head.status, 200);
  EXPECT_TRUE(head.body.empty());
}

}  // namespace
}  // namespace stride::view_test
