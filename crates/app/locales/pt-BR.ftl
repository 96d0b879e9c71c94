### integrators

integrators-join = { "; " }
integrators-legend-dp45-order = DP45: { $order }
integrators-overflow-note = estouro em t = { $time }
integrators-failed = falhou
integrators-stable-yes = sim
integrators-stable-no = não
integrators-method-euler = Euler explícito
integrators-method-symplectic-euler = Euler simplético
integrators-method-heun = Heun
integrators-method-rk4 = RK4
integrators-legend-symplectic-euler = Euler simpl. ×
integrators-legend-dp45 = DP45 ● passos
integrators-legend-growing = { $legend } ×{ $growth }/passo ↑
integrators-legend-order = { $legend }: { $order }
integrators-legend-no-fit = { $legend }: sem ajuste
integrators-legend-dp45-no-order = DP45: sem ordem
integrators-series-exact = exata
integrators-axis-error = erro |x_num − x_exact|
integrators-axis-step = passo h
integrators-axis-max-error = erro máximo
integrators-axis-re = parte real Re(hλ)
integrators-axis-im = parte imaginária Im(hλ)
integrators-axis-evaluations = avaliações do lado direito N
integrators-limit-up-to = estável para h ≤ { $step }
integrators-limit-every = estável para todo h
integrators-limit-none = instável para todo h
integrators-method-overflows = { $method } estoura em t = { $time } (×{ $growth } por passo)
integrators-method-diverges = { $method } diverge (×{ $growth } por passo), erro máximo { $error }
integrators-method-diverges-clipped = { $method } diverge (×{ $growth } por passo, cortado), erro máximo { $error }
integrators-method-bounded = { $method } permanece limitado (×{ $growth } por passo), erro máximo { $error }
integrators-dp45-words = DP45 deu { $steps ->
        [one] { $steps } passo
       *[other] { $steps } passos
    } (tolerância { $tolerance }), erro máximo { $error }
integrators-dp45-failed = DP45 falhou: { $reason }
integrators-failed-underflow = o passo ficou pequeno demais para avançar em t = { $time } (o problema pode ser rígido demais ou singular)
integrators-failed-max-steps = desistiu em t = { $time } após { $steps } passos
integrators-failed-non-finite = a solução tornou-se infinita ou indefinida em t = { $time } (tente um passo menor)
integrators-describe-response = Cada método comparado com a oscilação amortecida exata ao longo de { $duration } com h = { $step } ({ $steps } passos). { $methods }. O gráfico mostra ±{ $range } vezes a amplitude exata; as curvas que passam disso são cortadas na borda.
integrators-describe-response-last = Cada método comparado com a oscilação amortecida exata ao longo de { $duration } com h = { $step } ({ $steps } passos, o último de { $last } para terminar em T). { $methods }. O gráfico mostra ±{ $range } vezes a amplitude exata; as curvas que passam disso são cortadas na borda.
integrators-error-peak = { $method }: máximo { $error } em t = { $time }
integrators-error-peak-growing = { $method }: máximo { $error } em t = { $time }, crescente
integrators-error-none = { $method }: nenhum erro finito
integrators-error-no-method = Nenhum método está ativado.
integrators-describe-error = Erro |x_num − x_exact| em escala logarítmica nos pontos da malha de cada método (h = { $step }): { $methods }.
integrators-describe-error-clipped = Erro |x_num − x_exact| em escala logarítmica nos pontos da malha de cada método (h = { $step }): { $methods }. Erros acima de { $clip } são cortados no topo.
integrators-fit = { $method }: inclinação ajustada { $slope } (h = { $from } … { $to })
integrators-fit-overflows = { $method }: inclinação ajustada { $slope } (h = { $from } … { $to }), estoura para h ≥ { $limit }
integrators-no-fit = { $method }: sem ajuste (poucos pontos na faixa assintótica)
integrators-no-fit-overflows = { $method }: sem ajuste (poucos pontos na faixa assintótica), estoura para h ≥ { $limit }
integrators-slope = inclinação { $order }
integrators-describe-convergence = Erro máximo em { $points } pontos de verificação comuns em função do passo h, para até { $levels } passos que se reduzem à metade a partir de { $from } (no máximo { $budget } passos por método no total, { $euler_budget } para Euler explícito; passos mais finos são omitidos). { $methods }. Cada ordem é ajustada apenas na faixa assintótica, desenhada como o segmento grosso: os passos mais finos cujas inclinações locais concordam dentro de { $spread }, com erros abaixo de { $ceiling } e acima de 1e-10 de x₀. As inclinações de referência 1 e 4 são pontilhadas; o h atual é a linha vertical tracejada. DP45 não tem um único h: veja o gráfico de trabalho–precisão.
integrators-off-scale = { $name } = { $value } (fora da escala)
integrators-path = hλ à medida que h cresce
integrators-z-real-pair = z = hλ = { $z1 } e { $z2 }
integrators-region-inside = { $method }: dentro da sua região, |R| = { $growth }, { $limit }
integrators-region-outside = { $method }: fora da sua região, |R| = { $growth }, { $limit }
integrators-describe-stability = Regiões de estabilidade |R(z)| ≤ 1 no plano complexo de z = hλ (o interior de cada curva fechada; a de Euler explícito é o disco |1 + z| ≤ 1). Os dois polos do sistema com h = { $step } dão { $z }. { $methods }. Euler simplético não é uma aplicação escalar R(z): sua matriz de passo 2×2 tem aqui raio espectral { $radius }, { $limit }. DP45 escolhe os próprios passos e os mantém estáveis.
integrators-work-words = { $method }: de { $error_first } com { $work_first } avaliações a { $error_last } com { $work_last }
integrators-describe-work = Erro máximo em função do trabalho que custou, contado em avaliações do lado direito f, em eixos log–log, para cada método: os de passo fixo nos passos do estudo de convergência (erro nos seus pontos de verificação comuns), DP45 nas tolerâncias { $from } … { $to } (erro nos seus passos aceitos). Mais abaixo é mais preciso, mais à esquerda é mais barato; um método de ordem p cai com inclinação −p; as execuções do DP45 são pontos onde a tolerância define os passos e cruzes onde a estabilidade os define. { $methods }.
integrators-dp45-stability-runs = execuções cujos passos a estabilidade define (mais de { $share } dos passos a { $fraction } ou mais do seu maior passo estável): { $count }/{ $runs }
integrators-dp45-order = DP45: ordem observada { $order } (ajustada em { $from } … { $to } avaliações, onde a tolerância define os passos); { $runs }
integrators-dp45-no-order = DP45 não tem ordem observada: a estabilidade define seus passos, ou restam poucas execuções na faixa assintótica; { $runs }
integrators-title = Integradores numéricos e seu erro
integrators-summary = O oscilador livre integrado por Euler explícito, Euler simplético, Heun (RK2) e RK4 clássico com passo fixo h, e por Dormand–Prince 5(4) com passo adaptativo, cada um comparado com a solução exata. Um método de passo único multiplica cada modo por R(hλ) a cada passo: quando |R| > 1, os números crescem por melhor que o método aproxime a equação, e é por isso que Euler explícito faz explodir um oscilador pouco amortecido a menos que h < 2ζ/ωₙ. Quando ele é estável, reduzir h à metade divide o erro por 2^p, onde p é a ordem de convergência do método: o gráfico de convergência mede p. Desativar um método oculta suas curvas; suas leituras continuam sendo calculadas.
integrators-param-zeta = razão de amortecimento
integrators-param-wn = frequência natural
integrators-param-h = passo
integrators-param-T = duração
integrators-param-x0 = deslocamento inicial
integrators-param-tol = tolerância do DP45 (relativa; absoluta tol·x₀)
integrators-param-euler = Euler explícito
integrators-param-symplectic-euler = Euler simplético
integrators-param-heun = Heun (RK2)
integrators-param-rk4 = RK4
integrators-param-dp45 = Dormand–Prince 5(4), adaptativo
integrators-readout-h-used = passo usado: exatamente h (um último passo mais curto termina a execução em T)
integrators-readout-h-last = último passo, que termina a execução em T
integrators-readout-max-err-euler = erro máximo, Euler explícito
integrators-readout-max-err-symplectic-euler = erro máximo, Euler simplético
integrators-readout-max-err-heun = erro máximo, Heun
integrators-readout-max-err-rk4 = erro máximo, RK4
integrators-readout-max-err-dp45 = erro máximo, DP45
integrators-readout-order-euler = ordem ajustada, Euler explícito
integrators-readout-order-symplectic-euler = ordem ajustada, Euler simplético
integrators-readout-order-heun = ordem ajustada, Heun
integrators-readout-order-rk4 = ordem ajustada, RK4
integrators-readout-order-dp45 = ordem observada, DP45 (erro em função das avaliações de f, onde a tolerância define os passos)
integrators-readout-stable-euler = estável com este h, Euler explícito
integrators-readout-stable-symplectic-euler = estável com este h, Euler simplético
integrators-readout-stable-heun = estável com este h, Heun
integrators-readout-stable-rk4 = estável com este h, RK4
integrators-readout-growth-euler = crescimento por passo |R(hλ)|, Euler explícito
integrators-readout-growth-symplectic-euler = crescimento por passo (raio espectral), Euler simplético
integrators-readout-growth-heun = crescimento por passo |R(hλ)|, Heun
integrators-readout-growth-rk4 = crescimento por passo |R(hλ)|, RK4
integrators-readout-steps-dp45 = passos aceitos pelo DP45
integrators-plot-response = Soluções numéricas e a x(t) exata
integrators-plot-error = Erro ao longo do tempo
integrators-plot-convergence = Convergência: erro máximo em função do passo h
integrators-plot-work = Trabalho–precisão: erro máximo em função das avaliações de f
integrators-plot-stability = Regiões de estabilidade e z = hλ
integrators-preset-1 = Pouco amortecido, h = 0,3 s
integrators-preset-2 = Euler no limite da estabilidade, h = 0,04 s
integrators-preset-3 = RK4 além do seu limite, h = 1,6 s
integrators-preset-4 = Não amortecido, h = 0,1 s
integrators-preset-5 = Rígido e superamortecido ζ = 2, ωₙ = 20
integrators-table-caption = Os métodos
integrators-table-column-1 = método
integrators-table-column-2 = ordem p
integrators-table-column-3 = avaliações de f por passo
integrators-table-column-4 = fator de amplificação R(z)
integrators-table-column-5 = num oscilador não amortecido
integrators-table-euler-1 = Euler explícito
integrators-table-euler-2 = 1
integrators-table-euler-3 = 1
integrators-table-euler-4 = 1 + z
integrators-table-euler-5 = sempre cresce: |R(iωh)| = √(1 + ω²h²) > 1
integrators-table-symplectic-euler-1 = Euler simplético
integrators-table-symplectic-euler-2 = 1
integrators-table-symplectic-euler-3 = 2
integrators-table-symplectic-euler-4 = matriz 2×2, não um R escalar
integrators-table-symplectic-euler-5 = erro de energia limitado enquanto ωh ≤ 2
integrators-table-heun-1 = Heun (RK2)
integrators-table-heun-2 = 2
integrators-table-heun-3 = 2
integrators-table-heun-4 = 1 + z + z²/2
integrators-table-heun-5 = cresce lentamente: |R(iy)|² = 1 + y⁴/4
integrators-table-rk4-1 = RK4 clássico
integrators-table-rk4-2 = 4
integrators-table-rk4-3 = 4
integrators-table-rk4-4 = 1 + z + z²/2 + z³/6 + z⁴/24
integrators-table-rk4-5 = amortece levemente enquanto ωh ≤ 2√2
integrators-table-dp45-1 = Dormand–Prince 5(4)
integrators-table-dp45-2 = 5
integrators-table-dp45-3 = 6 (a primeira igual à última)
integrators-table-dp45-4 = adaptativo: h segue a estimativa de erro
integrators-table-dp45-5 = estável: passos rejeitados reduzem h

### nonlinear

nonlinear-effect-linear = linear
nonlinear-effect-hardening = mola enrijecedora
nonlinear-effect-softening = mola amolecedora
nonlinear-effect-stick-slip = adere-desliza
nonlinear-effect-bump-stop = impacto no batente
nonlinear-effect-asymmetric = amortecedor assimétrico
nonlinear-effect-several = várias ao mesmo tempo
nonlinear-effect-escaped = fuga
nonlinear-join = { "; " }
nonlinear-differ = diferem em até { $deviation } em t = { $time }
nonlinear-first-swing = primeira oscilação { $nonlinear } contra { $linear } da linear (razão { $ratio })
nonlinear-sticks-at = o atrito prende a massa em { $position } a partir de { $time }
nonlinear-escapes = a simulação não linear sai do gráfico (|x| > { $limit }) em { $time }
nonlinear-describe-response = { $effect }: ambas começam juntas; { $clauses }.
nonlinear-describe-phase = Plano de fase: ambas as trajetórias começam em x = { $x0 }, v = { $v0 }. A linear descreve uma espiral em direção a ({ $x_linear }, { $v_linear }); a não linear termina em x = { $x_end }, v = { $v_end }, com velocidade máxima de { $speed } contra { $speed_linear } da linear.
nonlinear-describe-spring = Força restauradora em função da extensão em ±{ $reach }: a mola linear é a reta k·x; no maior curso, { $travel }, a força não linear é { $force } contra { $linear } da linear.
nonlinear-describe-spring-stops = Força restauradora em função da extensão em ±{ $reach }: a mola linear é a reta k·x; no maior curso, { $travel }, a força não linear é { $force } contra { $linear } da linear, com os batentes somando { $rate } além de ±{ $gap }.
nonlinear-describe-damper = Força do amortecedor mais atrito em função da velocidade em ±{ $speed }: a +{ $speed } (distensão) vale { $rebound }, a −{ $speed } (compressão) { $compression }; o amortecedor médio do modelo linear dá ±{ $linear }.
nonlinear-describe-damper-friction = Força do amortecedor mais atrito em função da velocidade em ±{ $speed }: a +{ $speed } (distensão) vale { $rebound }, a −{ $speed } (compressão) { $compression }; o amortecedor médio do modelo linear dá ±{ $linear }; o atrito de deslizamento acrescenta um salto de ±{ $friction } em v = 0, e em repouso o atrito estático segura até ±{ $holding }.
nonlinear-axis-velocity-rebound = velocidade v (+ distensão)
nonlinear-series-stops = batentes ±{ $gap }
nonlinear-series-linear = modelo linear
nonlinear-series-nonlinear = não linear (RK4)
nonlinear-marker-sticks = adere
nonlinear-marker-start = início
nonlinear-series-linear-spring = k·x linear
nonlinear-series-spring = k·x + k₃·x³ + batentes
nonlinear-series-linear-damper = c̄·v linear
nonlinear-series-damper = amortecedor + atrito
nonlinear-schematic = Quarto de veículo em t = { $time }: suspensão estendida { $extension }.
nonlinear-schematic-pressing = Quarto de veículo em t = { $time }: suspensão estendida { $extension }, apoiada num batente.
nonlinear-schematic-clear = Quarto de veículo em t = { $time }: suspensão estendida { $extension }, sem tocar os batentes.
nonlinear-title = Além do modelo linear
nonlinear-summary = Uma suspensão real só é linear para movimentos pequenos. Aqui o quarto de veículo ganha uma mola cúbica (k₃ > 0 enrijecedora, k₃ < 0 amolecedora), um amortecedor mais duro na distensão (x′ > 0) do que na compressão, atrito de Coulomb nas articulações e batentes de borracha além de ±gap. O atrito alterna aderência e deslizamento: enquanto a massa desliza, ele freia com a força F_c; quando ela para, o atrito estático a segura até F_static, um múltiplo fixo de F_c, e ela só volta a se mover se a mola puxar com mais força. O movimento é integrado com RK4, cada parada localizada dentro do seu passo, e desenhado contra o modelo linear m·x″ + c̄·x′ + k·x = 0 (c̄ a constante média do amortecedor) a partir do mesmo início. Observe onde a previsão falha: o período depende da amplitude (a mola enrijecedora o encurta, a amolecedora o alonga), o atrito faz a amplitude cair em linha reta e depois prende a massa fora do centro de vez (adere-desliza), um batente transforma uma oscilação suave num impacto, e um amortecedor assimétrico desloca a posição média. Os valores padrão são um canto de carro plausível: 300 kg, 24 kN/m (1,4 Hz), um amortecedor de 1 500 N·s/m (ζ ≈ 0,28) e uma mola levemente progressiva. x é a extensão da suspensão a partir do equilíbrio estático (positiva = carroceria para cima).
nonlinear-param-m = massa suspensa
nonlinear-param-k = rigidez linear da mola
nonlinear-param-k3 = coeficiente cúbico da mola (+ enrijecedora, − amolecedora)
nonlinear-param-c-comp = constante do amortecedor na compressão
nonlinear-param-c-reb = constante do amortecedor na distensão
nonlinear-param-friction = força de atrito de Coulomb ao deslizar
nonlinear-param-stick-ratio = razão entre atrito estático e de deslizamento
nonlinear-param-gap = folga até o batente
nonlinear-param-k-stop = rigidez do batente (0 = sem batentes)
nonlinear-param-x0 = extensão inicial
nonlinear-param-v0 = velocidade inicial
nonlinear-readout-effect = não linearidade dominante
nonlinear-readout-period-ratio = razão dos períodos da primeira oscilação T_nonlinear / T_linear
nonlinear-readout-max-deviation = maior |x_nonlinear − x_linear|
nonlinear-readout-period-nonlinear = período não linear da primeira oscilação completa (três cruzamentos por zero)
nonlinear-readout-period-linear = período linear da primeira oscilação completa (= 2π/ω_d)
nonlinear-readout-max-travel = maior |x| (não linear)
nonlinear-readout-stick-position = o atrito prende a massa em
nonlinear-plot-response = Resposta não linear e linear x(t)
nonlinear-plot-phase = Plano de fase (x, v)
nonlinear-plot-spring = Força da mola e dos batentes
nonlinear-plot-damper = Força do amortecedor e do atrito
nonlinear-preset-1 = Linear (tudo desligado)
nonlinear-preset-2 = Mola enrijecedora
nonlinear-preset-3 = Mola amolecedora
nonlinear-preset-4 = Atrito adere–desliza
nonlinear-preset-5 = Impacto no batente
nonlinear-preset-6 = Amortecedor assimétrico
nonlinear-table-caption = Onde o modelo linear falha
nonlinear-table-column-1 = não linearidade
nonlinear-table-column-2 = lei de força
nonlinear-table-column-3 = o que o modelo linear não capta
nonlinear-table-column-4 = assinatura nos gráficos
nonlinear-table-linear-1 = Nenhuma (linear)
nonlinear-table-linear-2 = k·x + c·x′
nonlinear-table-linear-3 = nada: o modelo é exato
nonlinear-table-linear-4 = as duas curvas coincidem
nonlinear-table-hardening-spring-1 = Mola enrijecedora
nonlinear-table-hardening-spring-2 = k·x + k₃·x³, k₃ > 0
nonlinear-table-hardening-spring-3 = a frequência sobe com a amplitude
nonlinear-table-hardening-spring-4 = período mais curto enquanto a oscilação é grande; as curvas se afastam
nonlinear-table-softening-spring-1 = Mola amolecedora
nonlinear-table-softening-spring-2 = k·x + k₃·x³, k₃ < 0
nonlinear-table-softening-spring-3 = a frequência cai com a amplitude; além de √(−k/k₃) a mola cede
nonlinear-table-softening-spring-4 = período mais longo; um início grande pode escapar
nonlinear-table-stick-slip-1 = Atrito de Coulomb
nonlinear-table-stick-slip-2 = F_c·sgn(x′) ao deslizar; até F_static em repouso
nonlinear-table-stick-slip-3 = a amplitude cai cerca de 4F_c/k por ciclo, em linha reta, e depois a massa fica presa de vez onde |k·x| ≤ F_static
nonlinear-table-stick-slip-4 = envoltória reta; um final plano fora do zero
nonlinear-table-bump-stop-impact-1 = Batentes
nonlinear-table-bump-stop-impact-2 = k_stop·(|x| − gap) além de ±gap
nonlinear-table-bump-stop-impact-3 = um contato rígido e súbito: força grande, inversão rápida
nonlinear-table-bump-stop-impact-4 = picos cortados em ±gap; quebras no laço de fase
nonlinear-table-asymmetric-damper-1 = Amortecedor assimétrico
nonlinear-table-asymmetric-damper-2 = c_r·x′ na distensão, c_c·x′ na compressão
nonlinear-table-asymmetric-damper-3 = um deslocamento da posição média (efeito “jacking”) e semiciclos desiguais
nonlinear-table-asymmetric-damper-4 = decaimento desigual; a espiral de fase fica fora do centro
nonlinear-table-several-at-once-1 = Várias ao mesmo tempo
nonlinear-table-several-at-once-2 = soma das anteriores
nonlinear-table-several-at-once-3 = seus efeitos se somam e interagem
nonlinear-table-several-at-once-4 = ver cada linha
nonlinear-table-escaped-1 = Mola amolecedora além do seu limite
nonlinear-table-escaped-2 = k·x + k₃·x³ < 0 para |x| > √(−k/k₃)
nonlinear-table-escaped-3 = o modelo deixa de descrever uma suspensão
nonlinear-table-escaped-4 = a simulação é cortada onde |x| passa de 1 m

### uncertainty

uncertainty-quantity-zeta = razão de amortecimento ζ
uncertainty-quantity-f0 = frequência natural f0
uncertainty-quantity-q = fator de qualidade Q
uncertainty-quantity-bandwidth = largura de banda de meia potência
uncertainty-quantity-settling-time = tempo de acomodação da resposta livre (±5 %)
uncertainty-hist-title = Monte Carlo: { $quantity }
uncertainty-draws-provisional = { $draws } ({ $full } a caminho)
uncertainty-band-nominal-mass = m nominal
uncertainty-band-lowest-corner = canto de ζ mínimo
uncertainty-band-nominal = nominal
uncertainty-band-highest-corner = canto de ζ máximo
uncertainty-never = nunca
uncertainty-band-suspension = Resposta livre a partir de { $start } com a massa suspensa a +{ $percent } %, nominal e a −{ $percent } %
uncertainty-band-rlc = Tensão do capacitor a partir de 1 V no canto de ζ mínimo, no nominal e no canto de ζ máximo da caixa de tolerâncias
uncertainty-ignored-rlc = Os controles do RLC são ignorados.
uncertainty-ignored-suspension = Os controles da suspensão são ignorados.
uncertainty-zeta-undefined = ζ não está definido num extremo do intervalo
uncertainty-zeta-spans = ζ vai de { $low } a { $high }
uncertainty-describe-band = { $what }: { $zeta }; tempos de acomodação de 5 % (cruzes): { $first }, { $second } e { $third }. { $ignored }
uncertainty-dist-normal = normais (tolerância = 3σ)
uncertainty-dist-uniform = uniformes
uncertainty-spec-zeta = A janela de especificação de ζ, { $low }–{ $high }, está marcada; { $share } dos sorteios atendem a toda a especificação.
uncertainty-spec-settling-time = O limite de especificação, { $limit }, está marcado.
uncertainty-no-finite = Nenhum sorteio dá um valor finito de { $quantity }.
uncertainty-describe-histogram = Histograma de { $quantity } em { $draws } sorteios { $distribution }: de { $low } a { $high }, percentil 5: { $p5 }, percentil 95: { $p95 }.
uncertainty-describe-histogram-spec = Histograma de { $quantity } em { $draws } sorteios { $distribution }: de { $low } a { $high }, percentil 5: { $p5 }, percentil 95: { $p95 }. { $spec }
uncertainty-provisional-title = { $title } (provisório)
uncertainty-provisional-description = Provisório: a partir dos primeiros { $shown } sorteios enquanto a simulação de { $full } continua. { $description }
uncertainty-axis-capacitor-voltage = tensão do capacitor v_C
uncertainty-settling-band = faixa de acomodação de 5 %
uncertainty-axis-draws = sorteios
uncertainty-series-bins = sorteios por classe ({ $bins } classes)
uncertainty-no-finite-values = nenhum valor finito
uncertainty-spec-limit = limite de especificação
uncertainty-percentiles = percentis 5 e 95
uncertainty-title = Análise de tolerâncias
uncertainty-summary = Componentes reais não têm exatamente seu valor nominal. Escolha o sistema: o quarto de veículo (massa suspensa m, mola k e o amortecedor ajustado para ζ na massa nominal; a massa varia ±dm conforme a carga do veículo) ou o circuito RLC série (R, L e C, cada um dentro de ±dR, ±dL, ±dC). Só os controles do sistema escolhido são usados; o outro grupo é ignorado. Os intervalos exatos de ζ, ωₙ e Q vêm dos cantos da caixa de tolerâncias. A simulação de Monte Carlo sorteia N projetos (com semente: a mesma semente dá o mesmo resultado), uniformes dentro da tolerância ou normais com a tolerância como 3σ. O rendimento é a fração dos sorteios com ζ dentro da janela de especificação e um tempo de acomodação de 5 % (soltando do repouso) não maior que o limite.
uncertainty-param-system = sistema
uncertainty-param-system-suspension = suspensão de quarto de veículo
uncertainty-param-system-rlc = RLC série
uncertainty-param-m = suspensão: massa suspensa
uncertainty-param-k = suspensão: rigidez da mola
uncertainty-param-zeta = suspensão: ζ de projeto na massa nominal
uncertainty-param-dm = suspensão: tolerância da massa ±
uncertainty-param-R = RLC: resistência
uncertainty-param-L = RLC: indutância
uncertainty-param-C = RLC: capacitância
uncertainty-param-dR = RLC: tolerância do resistor ±
uncertainty-param-dL = RLC: tolerância do indutor ±
uncertainty-param-dC = RLC: tolerância do capacitor ±
uncertainty-param-dist = distribuição dos componentes
uncertainty-param-dist-uniform = uniforme dentro de ±tolerância
uncertainty-param-dist-normal = normal, tolerância = 3σ
uncertainty-param-N = sorteios de Monte Carlo
uncertainty-param-seed = semente aleatória
uncertainty-param-zeta-lo = especificação: ζ mínimo
uncertainty-param-zeta-hi = especificação: ζ máximo
uncertainty-param-ts-max = especificação: tempo de acomodação máximo
uncertainty-param-hist = segundo histograma
uncertainty-param-hist-zeta = razão de amortecimento ζ
uncertainty-param-hist-f0 = frequência natural f0
uncertainty-param-hist-q = fator de qualidade Q
uncertainty-param-hist-bandwidth = largura de banda
uncertainty-param-hist-settling-time = tempo de acomodação
uncertainty-readout-zeta-min = ζ, mínimo (exato)
uncertainty-readout-zeta-max = ζ, máximo (exato)
uncertainty-readout-wn-min = ωₙ, mínima (exata)
uncertainty-readout-wn-max = ωₙ, máxima (exata)
uncertainty-readout-Q-min = Q, mínimo (exato)
uncertainty-readout-Q-max = Q, máximo (exato)
uncertainty-readout-yield = rendimento (atende à especificação)
uncertainty-readout-zeta-p5 = ζ, percentil 5
uncertainty-readout-zeta-p95 = ζ, percentil 95
uncertainty-readout-Q-p5 = Q, percentil 5
uncertainty-readout-Q-p95 = Q, percentil 95
uncertainty-readout-draws = sorteios
uncertainty-readout-compute-time = tempo de cálculo do Monte Carlo
uncertainty-plot-band = Faixa de respostas livres dentro da tolerância
uncertainty-plot-zeta-hist = Monte Carlo: razão de amortecimento ζ
uncertainty-plot-hist = Monte Carlo: grandeza escolhida
uncertainty-preset-1 = Projeto com ζ = 1 e massa ±10 %
uncertainty-preset-2 = Projeto com ζ = 0,7 e massa ±10 %
uncertainty-preset-3 = RLC com componentes de 5 %
uncertainty-preset-4 = RLC com componentes de 20 %
