from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.equilibria_out import EquilibriaOut
from ...models.error_out import ErrorOut
from ...models.rest_configurations_request import RestConfigurationsRequest
from ...types import Response


def _get_kwargs(
    *,
    body: RestConfigurationsRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/rest-configurations",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> EquilibriaOut | ErrorOut | None:
    if response.status_code == 200:
        response_200 = EquilibriaOut.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if response.status_code == 504:
        response_504 = ErrorOut.from_dict(response.json())

        return response_504

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[EquilibriaOut | ErrorOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: RestConfigurationsRequest,
) -> Response[EquilibriaOut | ErrorOut]:
    """Every equilibrium under a dead tip load (F = 0: the rest configurations)

     All equilibria inside the physical range under the tip force `F = (fx, fy)` held fixed
    (`tensegrity_opt.analyses.equilibria.rest.find_equilibria_under_force`), each classified by the full
    Hessian of `E - F . tip`, sorted by that potential. `F = 0` is exact (`method: "exact"`, certified):
    the product of the segments' unloaded critical points; a bistable segment gives two wells.
    `stable_only` keeps the minima. For `F != 0`, `method: homotopy` is accepted for chains up to the
    server's `homotopy_max_segments`.

    Args:
        body (RestConfigurationsRequest): Every equilibrium under a dead tip load `F = (fx, fy)`;
            `F = 0` (default): the rest configurations.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[EquilibriaOut | ErrorOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: RestConfigurationsRequest,
) -> EquilibriaOut | ErrorOut | None:
    """Every equilibrium under a dead tip load (F = 0: the rest configurations)

     All equilibria inside the physical range under the tip force `F = (fx, fy)` held fixed
    (`tensegrity_opt.analyses.equilibria.rest.find_equilibria_under_force`), each classified by the full
    Hessian of `E - F . tip`, sorted by that potential. `F = 0` is exact (`method: "exact"`, certified):
    the product of the segments' unloaded critical points; a bistable segment gives two wells.
    `stable_only` keeps the minima. For `F != 0`, `method: homotopy` is accepted for chains up to the
    server's `homotopy_max_segments`.

    Args:
        body (RestConfigurationsRequest): Every equilibrium under a dead tip load `F = (fx, fy)`;
            `F = 0` (default): the rest configurations.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        EquilibriaOut | ErrorOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: RestConfigurationsRequest,
) -> Response[EquilibriaOut | ErrorOut]:
    """Every equilibrium under a dead tip load (F = 0: the rest configurations)

     All equilibria inside the physical range under the tip force `F = (fx, fy)` held fixed
    (`tensegrity_opt.analyses.equilibria.rest.find_equilibria_under_force`), each classified by the full
    Hessian of `E - F . tip`, sorted by that potential. `F = 0` is exact (`method: "exact"`, certified):
    the product of the segments' unloaded critical points; a bistable segment gives two wells.
    `stable_only` keeps the minima. For `F != 0`, `method: homotopy` is accepted for chains up to the
    server's `homotopy_max_segments`.

    Args:
        body (RestConfigurationsRequest): Every equilibrium under a dead tip load `F = (fx, fy)`;
            `F = 0` (default): the rest configurations.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[EquilibriaOut | ErrorOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: RestConfigurationsRequest,
) -> EquilibriaOut | ErrorOut | None:
    """Every equilibrium under a dead tip load (F = 0: the rest configurations)

     All equilibria inside the physical range under the tip force `F = (fx, fy)` held fixed
    (`tensegrity_opt.analyses.equilibria.rest.find_equilibria_under_force`), each classified by the full
    Hessian of `E - F . tip`, sorted by that potential. `F = 0` is exact (`method: "exact"`, certified):
    the product of the segments' unloaded critical points; a bistable segment gives two wells.
    `stable_only` keeps the minima. For `F != 0`, `method: homotopy` is accepted for chains up to the
    server's `homotopy_max_segments`.

    Args:
        body (RestConfigurationsRequest): Every equilibrium under a dead tip load `F = (fx, fy)`;
            `F = 0` (default): the rest configurations.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        EquilibriaOut | ErrorOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
